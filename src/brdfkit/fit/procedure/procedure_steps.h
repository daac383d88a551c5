#pragma once
// The pieces procedures share, and the procedures that are more than one fit_model call (one file
// each; procedure.cpp registers them).
#include <string_view>

#include "brdfkit/fit/procedure/procedure.h"

namespace brdfkit::fit {

// Seed 000 §5: per channel, the θd = 0 slice then the θh = 0 slice (bagher_procedure.cpp).
ProcedureResult bagher_procedure(const Model& model, MetricStore& store, const FitSettings& settings,
                                 const Progress& progress);

// Seed 004 §5.8 (hp_procedure.cpp).
ProcedureResult hp_two_step(const Model& model, MetricStore& store, const FitSettings& settings,
                            const Progress& progress);
ProcedureResult hp_one_step(const Model& model, MetricStore& store, const FitSettings& settings,
                            const Progress& progress);

// One fit_model call under `metric_id` on the store's data, honouring settings.per_channel_shape
// (per_channel_shape.h), with `starts` starts; metric_value is the fitting metric's value.
FitResult plain_fit(const Model& model, MetricStore& store, std::string_view metric_id, const FitSettings& settings,
                    int starts);

// Value of metric `id` for the model at `values` (coarsened like the fit).
double metric_value(std::string_view id, const Model& model, const ParamValues& values, MetricStore& store,
                    int coarsen);

}  // namespace brdfkit::fit
