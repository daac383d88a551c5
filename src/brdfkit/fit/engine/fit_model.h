#pragma once
// Fitting a model under a metric: the engine's one entry. The lobe-shape parameters by bounded
// nonlinear least squares (Ceres, bounds from the ParamTable, forward-difference derivatives), the
// colours solved inside every evaluation by bounded linear least squares where the residual is
// linear in ρ (variable projection, seed 002 §3, projected_objective.h), one lobe shape shared by
// R, G, B unless the model says otherwise. Under a residual not linear in ρ (low-e2) the colours
// are solver variables (log_residual_objective.h). Seeded multi-start: start 0 the best point of
// a scan that includes the table's defaults (start_scan.h), the others random (random_start.h);
// each start runs the coarse-to-fine levels of level_schedule.h.
//
// The pieces, one job a file: solver_variables (parameters ↔ solver variables), linear_structure
// (the colours, probed), sample_blocks (the domain at a stride), objective + its three kinds +
// cached_objective, finite_difference, ceres_adapter (one level), random_start, start_scan,
// level_schedule, stall_stop, box_least_squares.
#include <stdexcept>
#include <string>

#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/fit/settings/fit_settings.h"
#include "brdfkit/models/model.h"

namespace brdfkit::fit {

struct FitResult {
  ParamValues values;
  double metric_value = 0;  // the fitting metric at `values`, summed by the fit over its domain
  int iterations = 0;       // solver iterations, all starts and levels
  int best_start = 0;
  int scan_points = 0;      // points the scan of start 0 evaluated (0: start 0 was the defaults)
  double seconds = 0;       // wall time of the fit (domain construction excluded)
  bool converged = false;   // the best start's last level converged (or stalled)
  std::string message;      // the best start's solver report, one line
};

class FitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads the solver settings of `settings` (starts, seed, max_iterations, coarse_to_fine,
// scan_start). Throws SettingError for bad settings, InputError when the model has no parameter
// to fit or the metric is for reports only, FitError when no start produced a finite result.
// Cost: each evaluation is one parallel pass over the metric's domain (at the level's stride);
// memory: the domain's blocks at one stride plus the model's linear bases on them.
FitResult fit_model(const Model& model, const Metric& metric, const FitSettings& settings);

}  // namespace brdfkit::fit
