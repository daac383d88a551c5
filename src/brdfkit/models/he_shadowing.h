#pragma once
// Shadowing of He, Torrance, Sillion & Greenberg 1991 (Eq. 24–25), Smith's form for a Gaussian
// surface of RMS height σ0 and autocorrelation length τ, with a = τ cotθ / (2σ0):
//   S(θ) = (1 − ½ erfc(a)) / (Λ(a) + 1),   Λ(a) = ½ (e^{−a²}/(√π a) − erfc(a)).
// The paper prints Λ without the factor e^{−a²} (Eq. 25); its errata, Westin's reference code
// and Radiance's He.cal (Ward, after He's 1994 note) have it. With it, Λ is exactly Smith's Λ of
// a Beckmann distribution with α = 2σ0/τ (DESIGN.md §4), which the tests check.
// S(θi, θr) = S(θi) S(θr) (He 1991 Eq. 23).
#include <cmath>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/scalar_chain.h"

namespace brdfkit {

template <class T> T he_shadowing(const T& cos_theta, const T& sigma0, const T& tau) {
  using std::erfc;
  using std::exp;
  using std::sqrt;
  if (!(cos_theta > T(0))) return T(0);
  const T s2 = T(1) - cos_theta * cos_theta;
  // At normal incidence a = ∞ and S = 1; the guard also keeps Jets away from sqrt'(0).
  if (!(value_of(s2) > 1e-24)) return T(1);
  const T a = tau * cos_theta / (T(2) * sigma0 * sqrt(s2));
  const T erfc_a = erfc(a);
  T lambda = T(0.5) * (exp(-a * a) / (T(std::sqrt(kPi)) * a) - erfc_a);  // He 1991 Eq. 25 + errata
  if (!(lambda > T(0))) lambda = T(0);  // round-off for large a (DESIGN.md §4)
  return (T(1) - T(0.5) * erfc_a) / (lambda + T(1));  // He 1991 Eq. 24
}

}  // namespace brdfkit
