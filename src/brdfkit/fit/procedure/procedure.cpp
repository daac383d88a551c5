#include "brdfkit/fit/procedure/procedure.h"

#include <fmt/format.h>

#include "brdfkit/core/error.h"
#include "brdfkit/fit/procedure/per_channel_shape.h"
#include "brdfkit/fit/procedure/procedure_steps.h"

namespace brdfkit::fit {

namespace {

constexpr std::string_view kIds[] = {"ngan", "bagher", "low-e1", "low-e2", "hp-2step", "hp-1step"};

void check_id(std::string_view id) {
  for (auto k : kIds)
    if (k == id) return;
  std::string known;
  for (auto k : kIds) known += (known.empty() ? "" : ", ") + std::string(k);
  throw InputError("procedure '" + std::string(id) + "'", "unknown; known procedures: " + known);
}

}  // namespace

std::span<const std::string_view> procedure_ids() { return kIds; }

std::string_view procedure_metric(std::string_view id) {
  check_id(id);
  if (id.starts_with("hp-")) return "hp-rmse";
  return id;  // ngan, bagher, low-e1, low-e2: the procedure is named after its metric (DESIGN.md §8)
}

double metric_value(std::string_view id, const Model& model, const ParamValues& values, const MeasuredBrdf& data,
                    int coarsen) {
  const Metric m = make_metric(id, data, MetricOptions{coarsen});
  return m.value(model, values);
}

FitResult plain_fit(const Model& model, const MeasuredBrdf& data, std::string_view metric_id,
                    const ProcedureOptions& opt, int starts) {
  const Metric metric = make_metric(metric_id, data, MetricOptions{opt.coarsen});
  const FitOptions fo{starts, opt.seed, opt.max_iterations};
  if (!opt.per_channel_shape) return fit_model(model, metric, fo);
  const PerChannelShape wrapped(model);
  return fit_model(wrapped, metric, fo);
}

ProcedureResult run_procedure(std::string_view id, const Model& model, const MeasuredBrdf& data,
                              const ProcedureOptions& opt) {
  check_id(id);
  if (opt.coarsen < 1) throw InputError("procedure '" + std::string(id) + "'", "coarsening factor must be >= 1");
  if (!opt.metric.empty()) {
    bool known = false;
    for (auto m : metric_ids()) known = known || m == opt.metric;
    if (!known) make_metric(opt.metric, data);  // throws the metric's own "unknown" message
  }
  if (id == "bagher") return bagher_procedure(model, data, opt);
  if (id.starts_with("hp-")) return hp_procedure(id, model, data, opt);
  // ngan, low-e1, low-e2: one fit under the metric (seed 002 §3, seed 003 §5.1).
  ProcedureResult r;
  r.metric = opt.metric.empty() ? std::string(id) : opt.metric;
  if (opt.progress) opt.progress(fmt::format("{}: fitting {} under {}", id, model.name(), r.metric));
  r.fit = plain_fit(model, data, r.metric, opt, opt.starts);
  r.steps.push_back(fmt::format("fit all parameters under {} ({} shape, {} start(s)): {} = {:.6g}", r.metric,
                                opt.per_channel_shape ? "per-channel" : "shared", opt.starts, r.metric,
                                r.fit.metric_value));
  return r;
}

}  // namespace brdfkit::fit
