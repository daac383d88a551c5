#include "brdfkit/fit/engine/fit_model.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "brdfkit/core/error.h"
#include "brdfkit/fit/engine/cached_objective.h"
#include "brdfkit/fit/engine/ceres_adapter.h"
#include "brdfkit/fit/engine/level_schedule.h"
#include "brdfkit/fit/engine/linear_structure.h"
#include "brdfkit/fit/engine/log_residual_objective.h"
#include "brdfkit/fit/engine/plain_objective.h"
#include "brdfkit/fit/engine/projected_objective.h"
#include "brdfkit/fit/engine/random_start.h"
#include "brdfkit/fit/engine/start_scan.h"

namespace brdfkit::fit {

namespace {

struct StartOutcome {
  bool usable = false;
  double cost = 0;
  ParamValues values;
  bool converged = true;
  std::string message = "colours only: solved directly";
};

// The state of one fit: the model's variables, the domain at the current stride, the objective.
class Engine {
 public:
  Engine(const Model& model, const Metric& metric)
      : metric_(metric),
        structure_(probe_linear_structure(model, metric.transform() == Transform::Identity)),
        project_(metric.transform() == Transform::Identity && !structure_.colours.empty()),
        vars_(model.params(), solved_inside(structure_, project_)),
        ctx_{model, vars_, metric.transform(), {}, 0, {}} {
    std::unique_ptr<Objective> inner;
    if (project_) inner = std::make_unique<ProjectedObjective>(ctx_, structure_.bases);
    else if (!structure_.colours.empty()) inner = std::make_unique<LogResidualObjective>(ctx_, structure_.colours);
    else inner = std::make_unique<PlainObjective>(ctx_);
    objective_ = std::make_unique<CachedObjective>(std::move(inner), vars_.size());
    if (vars_.empty() && !project_)
      throw InputError("model '" + std::string(model.name()) + "'", "has no free parameter to fit");
  }

  StartOutcome run_start(int start, const FitSettings& settings, std::mt19937_64& rng, int& iterations,
                         int& scan_points);

 private:
  void set_stride(size_t s) {
    if (s == ctx_.stride && !ctx_.blocks.empty()) return;
    ctx_.stride = s;
    ctx_.blocks = sample_blocks(metric_, s, project_ ? BlockWeights::Squared : BlockWeights::Residual);
    objective_->reset(true);
  }
  void set_base(const ParamValues& pv) {
    ctx_.base = pv;
    objective_->reset(false);
  }
  ParamValues start_values(int start, std::mt19937_64& rng) const;
  std::vector<double> scanned(const std::vector<double>& x, int& points);

  const Metric& metric_;
  LinearStructure structure_;
  bool project_;
  SolverVariables vars_;
  FitContext ctx_;
  std::unique_ptr<CachedObjective> objective_;
};

// Start 0: the table's defaults; others: each variable drawn in its bounds.
ParamValues Engine::start_values(int start, std::mt19937_64& rng) const {
  ParamValues pv = ParamValues::defaults(ctx_.model.params());
  if (start > 0)
    for (size_t v = 0; v < vars_.size(); ++v) {
      const double x = random_start_value(vars_.spec(v), rng);
      for (int c = 0; c < 3; ++c)
        if (vars_[v].affects(c)) pv.values[size_t(c)][size_t(vars_[v].param)] = x;
    }
  return pv;
}

// The best point of the start scan from x, on a subsample of the domain.
std::vector<double> Engine::scanned(const std::vector<double>& x, int& points) {
  set_stride(scan_stride(domain_samples(metric_)));
  const StartScan scan = scan_start(ctx_.model.params(), vars_.params(), x, [&](const std::vector<double>& p) {
    ObjectiveValue o;
    ParamValues unused;
    return objective_->evaluate(p.data(), false, o, unused) ? o.cost : std::numeric_limits<double>::infinity();
  });
  points = scan.points;
  return scan.x;
}

StartOutcome Engine::run_start(int start, const FitSettings& settings, std::mt19937_64& rng, int& iterations,
                               int& scan_points) {
  const std::vector<size_t> strides = level_strides(domain_samples(metric_), settings.coarse_to_fine);
  ParamValues pv = start_values(start, rng);
  set_stride(strides.front());
  objective_->start_colours(pv);
  set_base(pv);
  std::vector<double> x(vars_.size());
  vars_.read(pv, x.data());
  if (start == 0 && settings.scan_start && !vars_.empty()) x = scanned(x, scan_points);
  StartOutcome out;
  out.usable = true;
  LevelOutcome previous;
  for (size_t level = 0; level < strides.size() && !vars_.empty() && out.usable; ++level) {
    const bool last = level + 1 == strides.size();
    set_stride(strides[level]);
    const LevelOutcome r = solve_level(*objective_, vars_, x, settings, last, level > 0 ? &previous : nullptr);
    previous = r;
    iterations += r.iterations;
    out.usable = r.usable;
    if (last) {
      out.converged = r.converged;
      out.message = r.message;
    } else if (r.usable && !objective_->best_point().empty()) {
      x = objective_->best_point();  // the next level starts from the lowest cost this one saw
    }
  }
  if (!out.usable) return out;
  set_stride(1);
  ObjectiveValue o;
  out.usable = objective_->evaluate(x.data(), false, o, out.values);
  out.cost = o.cost;
  for (const auto& ch : out.values.values)
    for (double v : ch) out.usable = out.usable && std::isfinite(v);
  return out;
}

}  // namespace

FitResult fit_model(const Model& model, const Metric& metric, const FitSettings& settings) {
  settings.validate();
  if (!metric.cached())
    throw InputError("metric '" + std::string(metric.id()) + "'",
                     "is for reports only (its domain is not kept: hp-rmse's grid is too large to keep); fit under "
                     "ngan, bagher, low-e1 or low-e2");
  metric.check_model(model);
  const auto t0 = std::chrono::steady_clock::now();
  Engine engine(model, metric);
  std::mt19937_64 rng(settings.seed);
  FitResult best;
  double best_cost = std::numeric_limits<double>::infinity();
  for (int start = 0; start < settings.starts; ++start) {
    const StartOutcome r = engine.run_start(start, settings, rng, best.iterations, best.scan_points);
    if (!r.usable || !(r.cost < best_cost)) continue;
    best_cost = r.cost;
    best.metric_value = metric.finish(r.cost);
    best.values = r.values;
    best.best_start = start;
    best.converged = r.converged;
    best.message = r.message;
  }
  if (!std::isfinite(best_cost))
    throw FitError("no start of " + std::to_string(settings.starts) + " gave a finite fit of model '" +
                   std::string(model.name()) + "' under metric '" + std::string(metric.id()) + "'");
  best.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return best;
}

}  // namespace brdfkit::fit
