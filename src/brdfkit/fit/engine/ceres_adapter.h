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
  std::string message;     // one line
};

// Solves from x (updated in place) on the objective's current stride. `last`: the level that
// decides the result converges tightly; coarse levels only bring the start close.
LevelOutcome solve_level(CachedObjective& objective, const SolverVariables& vars, std::vector<double>& x,
                         const FitSettings& settings, bool last);

}  // namespace brdfkit::fit
