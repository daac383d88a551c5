#include "brdfkit/shadowing/bagher_g1.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <limits>

#include "brdfkit/core/dense_solver_options.h"
#include "brdfkit/core/error.h"

namespace brdfkit {

namespace {

constexpr double kMaxW = 100.0;  // upper bound of w = π/2 − θ0

// G1 of seed 000 Eq. 9 in the parameters (log λ, w, log k), w = π/2 − θ0:
// c = log(1 + 1/λ)/w^k turns exp(c (θ − θ0)^k) into (1 + 1/λ)^(((θ − θ0)/w)^k).
template <class T> T g1_reparam(const T& log_lambda, const T& w, const T& log_k, double theta) {
  using std::exp;
  using std::log;
  using std::pow;
  const T theta0 = T(kPi / 2) - w;
  if (!(T(theta) > theta0)) return T(1);
  const T lambda = exp(log_lambda);
  const T y = pow((T(theta) - theta0) / w, exp(log_k));
  return T(1) + lambda * (T(1) - exp(y * log(T(1) + T(1) / lambda)));
}

struct Residual {
  double theta, target;
  template <class T> bool operator()(const T* x, T* r) const {
    r[0] = g1_reparam(x[0], x[1], x[2], theta) - T(target);
    return true;
  }
};

double sum_sq(const double* x, std::span<const double> theta, std::span<const double> g1) {
  double s = 0;
  for (size_t j = 0; j < theta.size(); ++j) {
    const double r = g1_reparam(x[0], x[1], x[2], theta[j]) - g1[j];
    s += r * r;
  }
  return s;
}

}  // namespace

std::vector<double> bagher_g1_angles(int n) {
  std::vector<double> t(size_t(std::max(n, 0)));
  for (int j = 0; j < n; ++j) t[size_t(j)] = (j + 0.5) * (kPi / 2) / n;
  return t;
}

namespace {

void check_inputs(std::span<const double> theta, std::span<const double> g1) {
  if (theta.empty()) throw InputError("fit_bagher_g1", "no angles to fit");
  if (theta.size() != g1.size()) throw InputError("fit_bagher_g1", "angles and G1 values differ in count");
  for (size_t j = 0; j < theta.size(); ++j)
    if (!std::isfinite(theta[j]) || !std::isfinite(g1[j]))
      throw InputError("fit_bagher_g1", "non-finite angle or G1 value at index " + std::to_string(j));
}

struct Start {
  double ss;
  double x[3];  // log λ, w, log k
};

// The sum of squares has separate basins (small λ with k ≈ 1–3, large λ with k ≈ 10–50 and
// θ0 < 0, both seen in the published fits): the best few points of a coarse grid over
// (log λ, w, log k), plus fixed starts in both basins scaled by where G1 starts to drop
// (neither set alone always finds the best minimum: sums differ up to 4× on published materials).
std::vector<Start> starts(std::span<const double> theta, std::span<const double> g1, double w_drop) {
  std::vector<Start> grid;
  for (int a = 0; a <= 14; ++a)
    for (int b = 0; b <= 8; ++b)
      for (int c = 0; c <= 14; ++c) {
        Start st;
        st.x[0] = std::log(1e-4) + a * (std::log(1e3) - std::log(1e-4)) / 14;
        st.x[1] = std::min(kMaxW, w_drop * std::pow(kMaxW / w_drop, b / 8.0));
        st.x[2] = std::log(0.5) + c * (std::log(500.0) - std::log(0.5)) / 14;
        st.ss = sum_sq(st.x, theta, g1);
        if (std::isfinite(st.ss)) grid.push_back(st);
      }
  const size_t n_grid = std::min<size_t>(6, grid.size());
  std::partial_sort(grid.begin(), grid.begin() + n_grid, grid.end(),
                    [](const Start& l, const Start& r) { return l.ss < r.ss; });
  grid.resize(n_grid);
  for (double lam0 : {0.3, 2.0, 20.0})
    for (double k0 : {1.5, 4.0, 20.0})
      for (double wf : {1.2, 2.0}) grid.push_back(Start{0, {std::log(lam0), std::min(4.0, wf * w_drop), std::log(k0)}});
  return grid;
}

// Levenberg-Marquardt from x, in place.
void polish(double* x, std::span<const double> theta, std::span<const double> g1) {
  ceres::Problem problem;
  for (size_t j = 0; j < theta.size(); ++j)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<Residual, 1, 3>(new Residual{theta[j], g1[j]}), nullptr, x);
  problem.SetParameterLowerBound(x, 0, std::log(1e-8));
  problem.SetParameterUpperBound(x, 0, std::log(1e8));
  // w and k may both grow large together (θ0 far below 0, k/w finite: the exp(−a(π/2 − θ))
  // limit of Eq. 9); a bound w ≤ 4 would be active at some grid points (θ0 = −2.4292).
  problem.SetParameterLowerBound(x, 1, 1e-6);
  problem.SetParameterUpperBound(x, 1, kMaxW);
  problem.SetParameterLowerBound(x, 2, std::log(0.2));
  problem.SetParameterUpperBound(x, 2, std::log(1e5));
  ceres::Solver::Summary summary;
  ceres::Solve(dense_solver_options(500, {.function = 1e-16, .gradient = 1e-20, .parameter = 1e-15}), &problem, &summary);
}

}  // namespace

BagherG1Fit fit_bagher_g1(std::span<const double> theta, std::span<const double> g1) {
  check_inputs(theta, g1);
  // Where G1 starts to drop sets the scale of w = π/2 − θ0 for the starts.
  double theta_drop = kPi / 2;
  for (size_t j = 0; j < theta.size(); ++j)
    if (g1[j] < 1.0 - 1e-4) theta_drop = std::min(theta_drop, theta[j]);
  const double w_drop = std::max(1e-3, kPi / 2 - theta_drop);

  double best[3] = {0, w_drop, std::log(2.0)};
  double best_ss = std::numeric_limits<double>::infinity();
  for (const Start& start : starts(theta, g1, w_drop)) {
    double x[3] = {start.x[0], start.x[1], start.x[2]};
    polish(x, theta, g1);
    const double ss = sum_sq(x, theta, g1);
    if (std::isfinite(ss) && ss < best_ss) {
      best_ss = ss;
      std::copy(x, x + 3, best);
    }
  }
  BagherG1Fit fit;
  fit.lambda = std::exp(best[0]);
  fit.k = std::exp(best[2]);
  fit.theta0 = kPi / 2 - best[1];
  fit.c = std::log1p(1.0 / fit.lambda) / std::pow(best[1], fit.k);
  fit.n = static_cast<int>(theta.size());
  fit.sum_sq = best_ss;
  fit.rms = std::sqrt(best_ss / fit.n);
  return fit;
}

}  // namespace brdfkit
