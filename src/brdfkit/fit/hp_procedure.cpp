// Holzschuch & Pacanowski 2015 (seed 004) §5.8, DESIGN.md §8 `hp-2step`, `hp-1step`.
//
// Fitting domain. The paper minimizes E = ∫ (meas − pred)² cos²θi dωo dθi (Eq. 29, = the square
// of hp-rmse, Eq. 31) with θi, θo < 1.4 rad. hp-rmse's own grid (θi every 1°, θo and φo every
// 0.25°: 37 million samples) is too large to keep, so the fit runs on the `low-e1` grid, which
// is the same integrand (cosθi ρ compared, weights sinθo Δθo Δφo Δθi, φo over the full circle,
// seed 003 Eq. 29–33) sampled with θi every 10° and θo, φo every 1° up to 80° (1.396 rad < 1.4):
// minimizing it minimizes a quadrature of Eq. 29. The result is reported under hp-rmse on its
// own grid (or under ProcedureOptions::metric, which then is also the fitting domain).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "brdfkit/core/error.h"
#include "brdfkit/fit/procedure_steps.h"

namespace brdfkit::fit {

namespace {

// Seed 004 §5.8: "With 10 runs, it converges to a solution that is better or equal to the
// two-step fitting method."
constexpr int kPaperRestarts = 10;

}  // namespace

ProcedureResult hp_procedure(std::string_view id, const Model& model, const MeasuredBrdf& data,
                             const ProcedureOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  ProcedureResult r;
  r.metric = opt.metric.empty() ? "hp-rmse" : opt.metric;
  const std::string domain = opt.metric.empty() ? "low-e1" : opt.metric;
  if (id == "hp-2step")
    throw InputError("procedure 'hp-2step'", "not available yet for model '" + std::string(model.name()) +
                                                 "': it needs the diffraction lobe of the Holzschuch-Pacanowski model");
  const int starts = std::max(opt.starts, kPaperRestarts);
  if (opt.progress)
    opt.progress(fmt::format("hp-1step: fitting {} on the {} grid, {} random restarts", model.name(), domain, starts));
  r.fit = plain_fit(model, data, domain, opt, starts);
  r.steps.push_back(fmt::format("fit all parameters at once on the {} grid (seed 004 Eq. 29), {} starts: {} = {:.6g}",
                                domain, starts, domain, r.fit.metric_value));
  if (r.metric != domain) {
    r.fit.metric_value = metric_value(r.metric, model, r.fit.values, data, opt.coarsen);
    r.steps.push_back(fmt::format("{} = {:.6g}", r.metric, r.fit.metric_value));
  }
  r.fit.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace brdfkit::fit
