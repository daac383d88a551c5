#pragma once
// Shadowing of He, Torrance, Sillion & Greenberg 1991 (Eq. 24–25), Smith's form for a Gaussian
// surface of RMS height σ0 and autocorrelation length τ, with a = τ cotθ / (2σ0):
//   S(θ) = (1 − ½ erfc(a)) / (Λ(a) + 1),   Λ(a) = ½ (e^{−a²}/(√π a) − erfc(a)).
// The paper prints Λ without the factor e^{−a²} (Eq. 25); its errata, Westin's reference code
// and Radiance's He.cal (Ward, after He's 1994 note) have it. With it, Λ is exactly Smith's Λ of
// a Beckmann distribution with α = 2σ0/τ (DESIGN.md §4), which the tests check.
// S(θi, θr) = S(θi) S(θr) (He 1991 Eq. 23).
//
// The effective roughness's K = tanθ erfc(τ / (2σ0 tanθ)) (Eq. 82–83) takes erfc of the same a:
// HeSlope computes a and erfc(a) once per direction for both.
#include <cmath>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/scalar_chain.h"

namespace brdfkit {

template <class T> struct HeSlope {
  enum class Kind { Below, Normal, Oblique } kind = Kind::Below;
  T tan_theta{}, a{}, erfc_a{};

  HeSlope(const T& cos_theta, const T& sigma0, const T& tau) {
    using std::erfc;
    using std::sqrt;
    if (!(cos_theta > T(0))) return;
    const T s2 = T(1) - cos_theta * cos_theta;
    // At normal incidence a = ∞: S = 1, K = 0; the guard also keeps Jets away from sqrt'(0).
    if (!(value_of(s2) > 1e-24)) {
      kind = Kind::Normal;
      return;
    }
    kind = Kind::Oblique;
    tan_theta = sqrt(s2) / cos_theta;
    a = tau / (T(2) * sigma0 * tan_theta);
    erfc_a = erfc(a);
  }

  T shadowing() const {
    using std::exp;
    if (kind != Kind::Oblique) return T(kind == Kind::Normal ? 1 : 0);
    T lambda = T(0.5) * (exp(-a * a) / (T(std::sqrt(kPi)) * a) - erfc_a);  // He 1991 Eq. 25 + errata
    if (!(lambda > T(0))) lambda = T(0);  // round-off for large a (DESIGN.md §4)
    return (T(1) - T(0.5) * erfc_a) / (lambda + T(1));  // He 1991 Eq. 24
  }

  // He 1991 Eq. 82–83.
  T k_factor() const { return kind == Kind::Oblique ? tan_theta * erfc_a : T(0); }
};

// What the model takes of one direction's slope: its shadowing S(θ) and its K(θ).
template <class T> struct HeSlopeTerms {
  T shadowing{}, k_factor{};
  HeSlopeTerms() = default;
  HeSlopeTerms(const T& cos_theta, const T& sigma0, const T& tau) {
    const HeSlope<T> s(cos_theta, sigma0, tau);
    shadowing = s.shadowing();
    k_factor = s.k_factor();
  }
};

template <class T> T he_shadowing(const T& cos_theta, const T& sigma0, const T& tau) {
  return HeSlope<T>(cos_theta, sigma0, tau).shadowing();
}

}  // namespace brdfkit
