#pragma once
// Effective roughness of He, Torrance, Sillion & Greenberg 1991 (Eq. 80–83): shadowing hides
// the deepest valleys, so the illuminated and visible surface looks smoother than σ0:
//   σ = σ0 / sqrt(1 + (z0/σ0)²),   √(π/2) z0 = (σ0/4) (Ki + Kr) exp(−z0²/(2σ0²)),
//   K = tanθ · erfc(τ / (2σ0 tanθ)).
// With x = z0/σ0 the root solves x e^{x²/2} = (Ki + Kr)/√(8π), found in doubles by Newton's
// method (Boost.Math); a Jet gets dx = d(rhs) / ((1 + x²) e^{x²/2}) (implicit function theorem).
// Symmetric in θi and θr, so the model stays reciprocal to the last bit.
#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <utility>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/scalar_chain.h"

namespace brdfkit {

namespace he_detail {

// He 1991 Eq. 82–83.
template <class T> T k_factor(const T& cos_theta, const T& sigma0, const T& tau) {
  using std::erfc;
  using std::sqrt;
  const T s2 = T(1) - cos_theta * cos_theta;
  if (!(value_of(s2) > 1e-24) || !(cos_theta > T(0))) return T(0);
  const T tan_theta = sqrt(s2) / cos_theta;
  return tan_theta * erfc(tau / (T(2) * sigma0 * tan_theta));
}

// Root of x e^{x²/2} = f0 (f0 ≥ 0). Brackets: x ≤ f0 when x ≤ 1, x ≤ sqrt(2 ln f0) when x > 1.
inline double solve_z0_ratio(double f0) {
  if (!(f0 > 0)) return 0.0;
  // Small f0 (most pairs when τ ≫ σ0: erfc is tiny away from grazing): the series inverse of
  // x e^{x²/2} = f0 (He 1991 Eq. 81 over σ0), x = f0 − f0³/2 + 5 f0⁵/8 + O(f0⁷), is exact in
  // doubles there, where Newton crawls for ~1 µs.
  if (f0 < 1e-3) {
    const double f2 = f0 * f0;
    return f0 * (1 - f2 * (0.5 - 0.625 * f2));
  }
  const double hi = f0 <= 1 ? f0 : std::max(1.0, std::sqrt(2 * std::log(f0)));
  auto f = [f0](double x) {
    const double e = std::exp(0.5 * x * x);
    return std::make_pair(x * e - f0, (1 + x * x) * e);
  };
  std::uintmax_t iterations = 100;
  return boost::math::tools::newton_raphson_iterate(f, 0.5 * hi, 0.0, hi, 50, iterations);
}

}  // namespace he_detail

template <class T> T he_effective_roughness(const T& cos_i, const T& cos_r, const T& sigma0, const T& tau) {
  using std::exp;
  using std::sqrt;
  const T f0 = (he_detail::k_factor(cos_i, sigma0, tau) + he_detail::k_factor(cos_r, sigma0, tau)) /
               T(std::sqrt(8 * kPi));  // He 1991 Eq. 81 divided by σ0
  const double x = he_detail::solve_z0_ratio(value_of(f0));
  const T xt = chain(x, 1.0 / ((1 + x * x) * std::exp(0.5 * x * x)), f0);
  return sigma0 / sqrt(T(1) + xt * xt);  // He 1991 Eq. 80
}

}  // namespace brdfkit
