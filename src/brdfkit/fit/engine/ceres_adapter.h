#pragma once
// One level of a fit as a Ceres problem: bounded Levenberg-Marquardt on the objective, with the
// stall stop (stall_stop.h).
#include <string>
#include <vector>

#include "brdfkit/fit/engine/cached_objective.h"
#include "brdfkit/fit/settings/fit_settings.h"

namespace brdfkit::fit {

struct LevelOutcome {
  bool usable = false;     // Ceres' IsSolutionUsable
  bool converged = false;  // Ceres' convergence, or a stall
  int iterations = 0;
  double radius = 0;       // the trust region's radius when the level ended
  std::string message;     // one line
};

// Solves from x (updated in place) on the objective's current stride. `last`: the level that
// decides the result converges tightly; coarse levels only bring the start close. `previous`: the
// outcome of the level whose optimum x is, for a level that refines it (null for the first).
LevelOutcome solve_level(CachedObjective& objective, const SolverVariables& vars, std::vector<double>& x,
                         const FitSettings& settings, bool last, const LevelOutcome* previous = nullptr);

}  // namespace brdfkit::fit
