#pragma once
// Ceres options of the small bounded least-squares problems solved beside the fitting engine
// (a handful of parameters: Bagher's G1 fit, the Bagher procedure's slice fits): dense QR, no
// logging, the caller's iteration limit and tolerances.
#include <ceres/solver.h>

namespace brdfkit {

struct SolverTolerances {
  double function, gradient, parameter;
};

inline ceres::Solver::Options dense_solver_options(int max_iterations, const SolverTolerances& tol) {
  ceres::Solver::Options o;
  o.linear_solver_type = ceres::DENSE_QR;
  o.max_num_iterations = max_iterations;
  o.function_tolerance = tol.function;
  o.gradient_tolerance = tol.gradient;
  o.parameter_tolerance = tol.parameter;
  o.logging_type = ceres::SILENT;
  return o;
}

}  // namespace brdfkit
