#include "brdfkit/ndf/sgd.h"

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>


namespace brdfkit {

Vec3d sgd_sample(double alpha, double p, const Vec2d& u) {
  const double s = 1.0 - p;
  const double total = upper_gamma(s, alpha);
  const double target = (1.0 - u.x()) * total;  // Γ(s, t) at the sample
  const double phi = 2 * kPi * u.y();
  if (!(target > 0.0)) return Vec3d(std::cos(phi), std::sin(phi), 0.0);  // u = 1: θ = π/2
  if (target >= total) return Vec3d(0, 0, 1);                            // u = 0: θ = 0
  // Γ(s, ·) decreases; compare in logs so that the tail (tiny Γ) keeps relative accuracy.
  const double log_target = std::log(target);
  auto f = [&](double t) { return std::log(upper_gamma(s, t)) - log_target; };
  double lo = alpha, hi = alpha + 1.0;
  while (f(hi) > 0.0) {
    lo = hi;
    hi = alpha + 2.0 * (hi - alpha);
    if (hi > 1e4) break;  // Γ(s, t) < 1e-4000: unreachable for u < 1 in double
  }
  std::uintmax_t iters = 100;
  const auto [a, b] = boost::math::tools::toms748_solve(f, lo, hi, boost::math::tools::eps_tolerance<double>(50), iters);
  const double t = 0.5 * (a + b);
  const double tan2 = std::max(0.0, alpha * (t - alpha));
  const double cos_t = 1.0 / std::sqrt(1.0 + tan2);
  const double sin_t = std::sqrt(tan2) * cos_t;
  return Vec3d(sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t);
}

}  // namespace brdfkit
