#pragma once
// Fitting a model under a metric (DESIGN.md §8 `ngan` procedure, seed 002 §3): the lobe-shape
// parameters by bounded nonlinear least squares (Ceres, bounds from the ParamTable, derivatives of
// the model by forward differences), the colours — the per-channel parameters flagged `linear` —
// solved inside every evaluation by bound-constrained linear least squares (variable
// projection), one lobe shape shared by R, G, B. No residual vector or Jacobian of the domain's
// size is ever stored: each evaluation reduces the domain, in parallel chunks summed in a fixed
// order, to the normal equations of the shape (variable_projection.cpp). Under a metric whose residual is not linear in ρ (low-e2's logarithm) the
// colours become ordinary solver parameters (seed 003 §5.1 fits every parameter of E2 at once).
// Seeded multi-start: start 0 the best point of a scan that includes the table's defaults
// (FitOptions::scan_start), the others uniform in the bounds (log-uniform where the bounds span
// more than two decades).
#include <cstdint>
#include <string>

#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/models/model.h"

namespace brdfkit::fit {

struct FitOptions {
  int starts = 1;
  std::uint64_t seed = 1;
  int max_iterations = 100;  // per start and level; a level also ends when it stalls (fit/stall_stop.h)
  // Solve first on every 67th / 17th / 7th sample of the domain (while ≥ 30 000 samples remain;
  // strides coprime with the domain's rows, fit/sample_stride.h),
  // each level starting from the lowest-cost point the previous one evaluated (its result, or a
  // last step its tolerances discarded), then on the whole domain: the last level
  // alone decides the result, so it is the full domain's optimum (DESIGN.md §7), reached in fewer
  // full-domain iterations (DESIGN.md §12).
  bool coarse_to_fine = true;
  // Start 0 is the best point of a deterministic scan of the shape parameters' box (colours solved
  // linearly at each point) instead of the table's defaults, which the scan includes
  // (fit/start_scan.h; issue #5: from the defaults some fits end in poorer basins).
  bool scan_start = true;
};

struct FitResult {
  ParamValues values;
  double metric_value = 0;  // the fitting metric at `values` (Metric::value)
  int iterations = 0;       // solver iterations, all starts
  int best_start = 0;
  int scan_points = 0;      // points the scan of start 0 evaluated (0: start 0 was the defaults)
  double seconds = 0;       // wall time of the fit (domain construction excluded)
  bool converged = false;   // the best start's solver reported convergence (or a stall)
  std::string message;      // the best start's solver report, one line
};

// Throws InputError when the model has no parameter to fit or the options are invalid, and
// FitError when no start produced a finite result.
FitResult fit_model(const Model& model, const Metric& metric, const FitOptions& options);

class FitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace brdfkit::fit
