#pragma once
// Effective roughness of He, Torrance, Sillion & Greenberg 1991 (Eq. 80–83): shadowing hides
// the deepest valleys, so the illuminated and visible surface looks smoother than σ0:
//   σ = σ0 / sqrt(1 + (z0/σ0)²),   √(π/2) z0 = (σ0/4) (Ki + Kr) exp(−z0²/(2σ0²)),
//   K = tanθ · erfc(τ / (2σ0 tanθ))   (he_shadowing.h: HeSlope::k_factor).
// With x = z0/σ0 the root solves x e^{x²/2} = f0 = (Ki + Kr)/√(8π), i.e. x² e^{x²} = f0², so
// x = sqrt(W0(f0²)) with W0 the principal branch of Lambert's W (Boost.Math); a Jet gets
// dx = df0 / ((1 + x²) e^{x²/2}) (implicit function theorem). Batches solve it eight pairs at a
// time on vector lanes instead (he_z0_ratio_lanes, he_batch_block.h), to Boost's value within 1e-15.
// Symmetric in θi and θr, so the model stays reciprocal to the last bit.
#include <boost/math/special_functions/lambert_w.hpp>
#include <cmath>
#include <type_traits>

#include "brdfkit/core/scalar_chain.h"
#include "brdfkit/core/vec.h"
#include "brdfkit/models/he_shadowing.h"

namespace brdfkit {

namespace he_detail {

// Root of x e^{x²/2} = f0 (f0 ≥ 0).
inline double solve_z0_ratio(double f0) { return f0 > 0 ? std::sqrt(boost::math::lambert_w0(f0 * f0)) : 0.0; }

}  // namespace he_detail

// σ from the two directions' K factors (their sum, Eq. 81).
template <class T> T he_effective_roughness_of(const T& k_sum, const T& sigma0) {
  using std::sqrt;
  const T f0 = k_sum / T(std::sqrt(8 * kPi));  // He 1991 Eq. 81 divided by σ0
  const double x = he_detail::solve_z0_ratio(value_of(f0));
  if constexpr (std::is_same_v<T, double>) return sigma0 / std::sqrt(1 + x * x);  // He 1991 Eq. 80
  else {
    const T xt = chain(x, 1.0 / ((1 + x * x) * std::exp(0.5 * x * x)), f0);  // the derivative: Jets only
    return sigma0 / sqrt(T(1) + xt * xt);  // He 1991 Eq. 80
  }
}

template <class T> T he_effective_roughness(const T& cos_i, const T& cos_r, const T& sigma0, const T& tau) {
  return he_effective_roughness_of(HeSlope<T>(cos_i, sigma0, tau).k_factor() + HeSlope<T>(cos_r, sigma0, tau).k_factor(), sigma0);
}

}  // namespace brdfkit
