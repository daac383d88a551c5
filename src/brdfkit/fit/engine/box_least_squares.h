#pragma once
// Tiny bound-constrained linear least squares on normal equations: the colour sub-problem of
// variable projection (seed 002 §3), a handful of unknowns per channel.
#include <Eigen/Core>

namespace brdfkit::fit {

// Minimizes ½ xᵀA x − yᵀx subject to lo ≤ x ≤ hi (A symmetric positive semi-definite, the
// normal matrix of a least-squares problem; hi may be +inf). With lo = 0 and hi = ∞ this is NNLS.
// Exact: every combination of free / at-lower / at-upper variables is solved and the best
// feasible one kept (3^K systems, K ≤ 6 enforced), so it needs no iteration and no tolerance;
// singular free blocks take the minimum-norm solution. Eigen 3.4 ships no NNLS module.
Eigen::VectorXd box_least_squares(const Eigen::MatrixXd& A, const Eigen::VectorXd& y, const Eigen::VectorXd& lo,
                                  const Eigen::VectorXd& hi);

}  // namespace brdfkit::fit
