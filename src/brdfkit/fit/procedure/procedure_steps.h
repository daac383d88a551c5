#pragma once
// The procedures that are more than one fit_model call, one file each (procedure.cpp dispatches).
#include "brdfkit/fit/procedure/procedure.h"

namespace brdfkit::fit {

// Seed 000 §5: per channel, the θd = 0 slice then the θh = 0 slice (bagher_procedure.cpp).
ProcedureResult bagher_procedure(const Model& model, const MeasuredBrdf& data, const ProcedureOptions& opt);

// Seed 004 §5.8: hp-2step and hp-1step (hp_procedure.cpp).
ProcedureResult hp_procedure(std::string_view id, const Model& model, const MeasuredBrdf& data,
                             const ProcedureOptions& opt);

// One fit_model call under `metric_id` (the procedure's own or opt.metric), honouring
// opt.per_channel_shape; the result's metric_value is the fitting metric's value.
FitResult plain_fit(const Model& model, const MeasuredBrdf& data, std::string_view metric_id,
                    const ProcedureOptions& opt, int starts);

// Value of metric `id` for the model at `values` (coarsened like the fit).
double metric_value(std::string_view id, const Model& model, const ParamValues& values, const MeasuredBrdf& data,
                    int coarsen);

}  // namespace brdfkit::fit
