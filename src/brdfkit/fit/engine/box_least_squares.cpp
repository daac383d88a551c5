#include "brdfkit/fit/engine/box_least_squares.h"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace brdfkit::fit {

Eigen::VectorXd box_least_squares(const Eigen::MatrixXd& A, const Eigen::VectorXd& y, const Eigen::VectorXd& lo,
                                  const Eigen::VectorXd& hi) {
  const int n = int(y.size());
  if (n > 6) throw std::invalid_argument("box_least_squares: more than 6 unknowns");
  int combos = 1;
  for (int i = 0; i < n; ++i) combos *= 3;
  // Feasibility slack relative to the problem's scale, for round-off in the free solve.
  const double slack = 1e-12 * (1.0 + lo.cwiseAbs().maxCoeff()) + 1e-12;
  Eigen::VectorXd best = lo.cwiseMax(Eigen::VectorXd::Zero(n)).cwiseMin(hi);
  double best_q = std::numeric_limits<double>::infinity();
  std::vector<int> state(static_cast<size_t>(n));
  for (int code = 0; code < combos; ++code) {
    int c = code;
    std::vector<int> free_idx;
    Eigen::VectorXd x(n);
    bool skip = false;
    for (int i = 0; i < n; ++i) {
      state[size_t(i)] = c % 3;  // 0 free, 1 at lower, 2 at upper
      c /= 3;
      if (state[size_t(i)] == 0) free_idx.push_back(i);
      else if (state[size_t(i)] == 1) x[i] = lo[i];
      else if (std::isfinite(hi[i])) x[i] = hi[i];
      else skip = true;
      if (state[size_t(i)] == 1 && !std::isfinite(lo[i])) skip = true;
    }
    if (skip) continue;
    const int m = int(free_idx.size());
    if (m > 0) {
      Eigen::MatrixXd Aff(m, m);
      Eigen::VectorXd rhs(m);
      for (int a = 0; a < m; ++a) {
        rhs[a] = y[free_idx[size_t(a)]];
        for (int i = 0; i < n; ++i)
          if (state[size_t(i)] != 0) rhs[a] -= A(free_idx[size_t(a)], i) * x[i];
        for (int b = 0; b < m; ++b) Aff(a, b) = A(free_idx[size_t(a)], free_idx[size_t(b)]);
      }
      const Eigen::VectorXd xf = Aff.completeOrthogonalDecomposition().solve(rhs);
      bool feasible = xf.allFinite();
      for (int a = 0; a < m && feasible; ++a) {
        const int i = free_idx[size_t(a)];
        feasible = xf[a] >= lo[i] - slack && xf[a] <= hi[i] + slack;
        x[i] = std::min(std::max(xf[a], lo[i]), hi[i]);
      }
      if (!feasible) continue;
    }
    const double q = 0.5 * x.dot(A * x) - y.dot(x);
    if (q < best_q) {
      best_q = q;
      best = x;
    }
  }
  return best;
}

}  // namespace brdfkit::fit
