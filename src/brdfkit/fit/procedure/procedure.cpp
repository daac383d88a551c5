#include "brdfkit/fit/procedure/procedure.h"

#include <fmt/format.h>

#include "brdfkit/core/error.h"
#include "brdfkit/fit/procedure/per_channel_shape.h"
#include "brdfkit/fit/procedure/procedure_steps.h"
#include "brdfkit/fit/procedure/retabled_model.h"
#include "brdfkit/fit/procedure/search_box.h"

namespace brdfkit::fit {

namespace {

// Seed 002 §3 and seed 003 §5.1: one fit under the procedure's metric.
template <const char* kMetric>
ProcedureResult single_fit(const Model& model, MetricStore& store, const FitSettings& settings,
                           const Progress& progress) {
  ProcedureResult r;
  r.metric = settings.metric.empty() ? std::string(kMetric) : settings.metric;
  if (progress) progress(fmt::format("{}: fitting {} under {}", kMetric, model.name(), r.metric));
  r.fit = plain_fit(model, store, r.metric, settings, settings.starts);
  r.steps.push_back(fmt::format("fit all parameters under {} ({} shape, {} start(s)): {} = {:.6g}", r.metric,
                                settings.per_channel_shape ? "per-channel" : "shared", settings.starts, r.metric,
                                r.fit.metric_value));
  return r;
}

constexpr char kNgan[] = "ngan", kLowE1[] = "low-e1", kLowE2[] = "low-e2";

}  // namespace

const Registry<Procedure>& procedure_registry() {
  static const Registry<Procedure> registry = [] {
    Registry<Procedure> r("procedure");
    r.add("ngan", {"ngan", "lobe shape by bounded least squares, colours by projection (seed 002 §3)", &single_fit<kNgan>})
        .add("bagher", {"bagher", "per channel, the θd = 0 then the θh = 0 slice (seed 000 §5)", &bagher_procedure})
        .add("low-e1", {"low-e1", "every parameter under E1 (seed 003 §5.1)", &single_fit<kLowE1>})
        .add("low-e2", {"low-e2", "every parameter under E2 (seed 003 §5.1)", &single_fit<kLowE2>})
        .add("hp-2step", {"hp-rmse", "diffuse + diffraction first, then reflection (seed 004 §5.8)", &hp_two_step})
        .add("hp-1step", {"hp-rmse", "all parameters at once, random restarts (seed 004 §5.8)", &hp_one_step});
    return r;
  }();
  return registry;
}

std::string fitting_metric(const FitSettings& settings) {
  if (settings.procedure.empty()) return settings.fitting_metric("");
  const Procedure* p = procedure_registry().find(settings.procedure);
  if (!p) throw procedure_registry().unknown_setting("procedure", settings.procedure);
  return settings.fitting_metric(std::string(p->metric));
}

void validate(const FitSettings& settings) {
  settings.validate();
  fitting_metric(settings);
}

FitResult plain_fit(const Model& model, MetricStore& store, std::string_view metric_id, const FitSettings& settings,
                    int starts) {
  const std::shared_ptr<const Metric> metric = store.metric(metric_id, MetricOptions{settings.coarsen});
  FitSettings s = settings;
  s.starts = starts;
  if (!settings.per_channel_shape) return fit_model(model, *metric, s);
  const RetabledModel wrapped(model, per_channel_shape_table(model));
  return fit_model(wrapped, *metric, s);
}

double metric_value(std::string_view id, const Model& model, const ParamValues& values, MetricStore& store,
                    int coarsen) {
  return store.metric(id, MetricOptions{coarsen})->value(model, values);
}

ProcedureResult run_procedure(const Model& model, MetricStore& store, const FitSettings& settings,
                              const Progress& progress) {
  validate(settings);
  if (!settings.bounds.empty()) {
    // Every procedure and the solver read the box from the model's table.
    const RetabledModel boxed(model, with_search_bounds(model, settings.bounds));
    FitSettings s = settings;
    s.bounds.clear();
    return run_procedure(boxed, store, s, progress);
  }
  if (settings.procedure.empty()) {
    // A plain fit under a metric is the `ngan` preset with its metric replaced.
    FitSettings s = settings;
    s.metric = fitting_metric(settings);
    return single_fit<kNgan>(model, store, s, progress);
  }
  return procedure_registry().get(settings.procedure).run(model, store, settings, progress);
}

ProcedureResult run_procedure(const Model& model, const MeasuredBrdf& data, const FitSettings& settings,
                              const Progress& progress) {
  MetricStore store(data);
  return run_procedure(model, store, settings, progress);
}

}  // namespace brdfkit::fit
