#include "brdfkit/ndf/sgd.h"

#include <boost/math/special_functions/gamma.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>


namespace brdfkit {

namespace {

// t ≥ x with Γ(s, t) = target ≤ Γ(s, x), s ≤ 0 (no regularized form), by toms748.
double solve_upper_gamma(double s, double x, double target) {
  // Γ(s, ·) decreases; compare in logs so that the tail (tiny Γ) keeps relative accuracy.
  const double log_target = std::log(target);
  auto f = [&](double t) { return std::log(upper_gamma(s, t)) - log_target; };
  double lo = x, hi = x + 1.0;
  while (f(hi) > 0.0) {
    lo = hi;
    hi = x + 2.0 * (hi - x);
    if (hi > 700.0) break;  // e^{−700}: below any target reachable with u < 1 in double
  }
  std::uintmax_t iters = 100;
  const auto [a, b] = boost::math::tools::toms748_solve(f, lo, hi, boost::math::tools::eps_tolerance<double>(50), iters);
  return 0.5 * (a + b);
}

}  // namespace

Vec3d sgd_sample(double alpha, double p, const Vec2d& u) {
  const double s = 1.0 - p;
  const double total = upper_gamma_cached(s, alpha);
  const double target = (1.0 - u.x()) * total;  // Γ(s, t) at the sample
  const double phi = 2 * kPi * u.y();
  if (!(target > 0.0)) return Vec3d(std::cos(phi), std::sin(phi), 0.0);  // u = 1: θ = π/2
  if (target >= total) return Vec3d(0, 0, 1);                            // u = 0: θ = 0
  double t;
  if (s > 0.0) {
    // Γ(s, t) = Γ(s) Q(s, t): the regularized inverse solves it directly.
    t = boost::math::gamma_q_inv(s, (1.0 - u.x()) * boost::math::gamma_q(s, alpha));
  } else {
    t = solve_upper_gamma(s, alpha, target);
  }
  const double tan2 = std::max(0.0, alpha * (t - alpha));
  const double cos_t = 1.0 / std::sqrt(1.0 + tan2);
  const double sin_t = std::sqrt(tan2) * cos_t;
  return Vec3d(sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t);
}

}  // namespace brdfkit
