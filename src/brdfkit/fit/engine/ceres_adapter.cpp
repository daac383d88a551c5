#include "brdfkit/fit/engine/ceres_adapter.h"

#include <ceres/ceres.h>
#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "brdfkit/fit/engine/stall_stop.h"

namespace brdfkit::fit {

namespace {

using Eigen::Index;

// The objective as a Ceres problem of n + 1 residuals instead of the domain's millions: with
// JᵀJ = Q Λ Qᵀ, the residuals r̃ = Λ^{-½} Qᵀ Jᵀr and e = √(cost − |r̃|²) with Jacobian [Λ^{½} Qᵀ; 0]
// have the same cost, gradient and Gauss-Newton matrix as the full residual, so every
// Levenberg-Marquardt step and acceptance test is the one the full problem would take.
class CompressedCost final : public ceres::CostFunction {
 public:
  CompressedCost(CachedObjective& objective, size_t n) : objective_(objective), n_(n) {
    set_num_residuals(int(n_ + 1));
    mutable_parameter_block_sizes()->push_back(int(n_));
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const bool derivatives = jacobians && jacobians[0];
    ObjectiveValue o;
    ParamValues unused;
    if (!objective_.evaluate(parameters[0], derivatives, o, unused)) return false;
    std::fill(residuals, residuals + n_ + 1, 0.0);
    if (!derivatives) {
      residuals[n_] = std::sqrt(o.cost);
      return true;
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(o.jtj);
    const Eigen::VectorXd& lambda = eig.eigenvalues();
    const Eigen::MatrixXd& Q = eig.eigenvectors();
    const double floor = 1e-14 * std::max(lambda.cwiseAbs().maxCoeff(), 1e-300);
    double* J = jacobians[0];  // row-major (n + 1) × n
    std::fill(J, J + (n_ + 1) * n_, 0.0);
    double projected = 0;
    for (size_t i = 0; i < n_; ++i) {
      const double l = lambda[Index(i)];
      if (!(l > floor)) continue;
      const double s = std::sqrt(l);
      residuals[i] = Q.col(Index(i)).dot(o.gradient) / s;
      projected += residuals[i] * residuals[i];
      for (size_t v = 0; v < n_; ++v) J[i * n_ + v] = s * Q(Index(v), Index(i));
    }
    residuals[n_] = std::sqrt(std::max(0.0, o.cost - projected));
    return true;
  }

 private:
  CachedObjective& objective_;
  size_t n_;
};

}  // namespace

LevelOutcome solve_level(CachedObjective& objective, const SolverVariables& vars, std::vector<double>& x,
                         const FitSettings& settings, bool last, const LevelOutcome* previous) {
  const size_t n = vars.size();
  ceres::Problem::Options popt;
  popt.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem problem(popt);
  problem.AddResidualBlock(new CompressedCost(objective, n), nullptr, x.data());
  for (size_t v = 0; v < n; ++v) {
    problem.SetParameterLowerBound(x.data(), int(v), vars.spec(v).lower);
    problem.SetParameterUpperBound(x.data(), int(v), vars.spec(v).upper);
  }
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = settings.max_iterations;
  so.function_tolerance = last ? 1e-12 : 1e-8;
  so.gradient_tolerance = last ? 1e-14 : 1e-10;
  so.parameter_tolerance = last ? 1e-10 : 1e-6;
  so.logging_type = ceres::SILENT;
  // Bounds make Ceres run a projected Armijo line search along every step; its default cubic
  // interpolation asks for the gradient at each trial point, here a whole Jacobian (one sweep of
  // the domain per variable) that a rejected trial throws away. Quadratic interpolation needs
  // only the trial's cost, and an accepted step's Jacobian is then computed once.
  so.line_search_interpolation_type = ceres::QUADRATIC;
  // A level refining the previous level's optimum starts from the trust region that level ended
  // with, not Ceres' default radius of 1e4. From that radius the first steps of a refining level
  // reach far past the optimum nearby; the line search cuts each back, and Ceres judges it
  // against the model's decrease for the whole step (trust_region_minimizer.cc, ceres-solver
  // issue 187), so the radius only halves, step after step: vch_golden_yellow's He took 22
  // steps on the whole grid, at ratios of 0.002-0.72, while its radius fell from 1e4 to 0.08.
  if (previous && previous->radius > 0) so.initial_trust_region_radius = previous->radius;
  so.num_threads = 1;  // the objective is parallel inside
  StallStop stall;
  so.callbacks.push_back(&stall);
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  LevelOutcome out;
  out.iterations = int(summary.iterations.size()) - 1;
  out.radius = summary.iterations.empty() ? 0.0 : summary.iterations.back().trust_region_radius;
  out.usable = summary.IsSolutionUsable();
  out.converged = summary.termination_type == ceres::CONVERGENCE || stall.stalled();
  out.message = stall.stalled() ? fmt::format("Stalled: the last {} steps lowered the cost by < {:g} relative.",
                                              stall.stalled()->window, stall.stalled()->relative)
                                : summary.message;
  return out;
}

}  // namespace brdfkit::fit
