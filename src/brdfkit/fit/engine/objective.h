#pragma once
// The objective a fit minimizes, as the solver sees it: at a point x of the solver's variables,
// cost = Σ r² over the metric's samples (its scale included) and, with derivatives, the
// Gauss-Newton pieces Jᵀr and JᵀJ. One file per kind (projected_objective.h, plain_objective.h,
// log_residual_objective.h); cached_objective.h wraps any of them with what the solver repeats.
// No residual vector or Jacobian of the domain's size is ever stored: each evaluation reduces the
// domain, in parallel blocks summed in a fixed order (core/ordered_reduce.h), to these pieces.
#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "brdfkit/fit/engine/sample_blocks.h"
#include "brdfkit/fit/engine/solver_variables.h"
#include "brdfkit/fit/metric/residual.h"
#include "brdfkit/models/model.h"

namespace brdfkit::fit {

struct ObjectiveValue {
  double cost = 0;
  Eigen::VectorXd gradient;  // Jᵀr
  Eigen::MatrixXd jtj;       // JᵀJ
};

// What the objectives of one fit read: the model, the solver's variables, the domain's blocks at
// the current stride, and the values the variables are written over (fixed parameters, and
// colours where the objective does not solve them). The fit driver owns it and tells the
// objective (Objective::reset) when the blocks or the base change.
struct FitContext {
  const Model& model;
  const SolverVariables& vars;
  Transform transform = Transform::Identity;
  std::vector<SampleBlock> blocks;
  std::size_t stride = 0;
  ParamValues base;

  // base with the variables set to x.
  ParamValues values_at(const double* x) const {
    ParamValues pv = base;
    vars.write(x, pv);
    return pv;
  }
};

class Objective {
 public:
  virtual ~Objective() = default;
  // The context's blocks (a new stride: `new_blocks`) or its base changed: drop what was computed
  // for the old ones.
  virtual void reset(bool new_blocks) = 0;
  // The objective at x. `values` receives the model's full parameter values there (with the
  // colours the objective solved, if it solves any). False when the model is not finite on the
  // domain.
  virtual bool evaluate(const double* x, bool derivatives, ObjectiveValue& out, ParamValues& values) = 0;
  // Sets a start's colours to fit its shape, for objectives whose colours are solver variables.
  virtual void start_colours(ParamValues&) {}
};

}  // namespace brdfkit::fit
