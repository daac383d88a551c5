#pragma once
// The seeds' fitting procedures (DESIGN.md §8) as presets over fit_model: which metric, which
// steps, which parameters are shared by R, G, B. Any model can be fitted under any metric with
// shared or per-channel shape parameters; the procedures are presets.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "brdfkit/core/registry.h"
#include "brdfkit/fit/engine/fit_model.h"
#include "brdfkit/fit/metric/metric_store.h"
#include "brdfkit/fit/settings/fit_settings.h"
#include "brdfkit/measured/measured_brdf.h"
#include "brdfkit/models/model.h"

namespace brdfkit::fit {

struct ProcedureResult {
  FitResult fit;
  std::string metric;              // the fitting metric: the procedure's, or FitSettings::metric
  std::vector<std::string> steps;  // what the procedure did, one line each
};

// Optional one-line progress messages of the steps.
using Progress = std::function<void(std::string_view)>;

struct Procedure {
  std::string_view metric;       // the metric it optimizes and reports first
  std::string_view description;  // one line with its source
  ProcedureResult (*run)(const Model& model, MetricStore& store, const FitSettings& settings, const Progress& progress);
};

// ngan, bagher, low-e1, low-e2, hp-2step, hp-1step, in that order.
const Registry<Procedure>& procedure_registry();

// The fitting metric of these settings: FitSettings::metric, else the procedure's, else ngan.
// SettingError for an unknown procedure.
std::string fitting_metric(const FitSettings& settings);
// FitSettings::validate plus the procedure's name.
void validate(const FitSettings& settings);

// Runs settings.procedure (empty: a plain fit under fitting_metric(settings): variable
// projection of the colours inside a bounded fit of the shape, DESIGN.md §8) on the store's data.
// Throws SettingError for bad settings, InputError for an incompatible model or data the metric
// cannot answer, FitError when no start gives a finite fit.
ProcedureResult run_procedure(const Model& model, MetricStore& store, const FitSettings& settings,
                              const Progress& progress = {});
// The same on data without a store of its own (the metric domains are built for this run).
ProcedureResult run_procedure(const Model& model, const MeasuredBrdf& data, const FitSettings& settings,
                              const Progress& progress = {});

}  // namespace brdfkit::fit
