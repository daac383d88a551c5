#pragma once
// Beckmann distribution: P22(x) = exp(−x/α²)/(π α²), x = tan²θ (seed 000 Table 1, DESIGN.md §3).
//
// The shape every distribution in ndf/ follows (pbrt-v4's TrowbridgeReitzDistribution in spirit):
// a value type templated on the scalar (double or ceres::Jet), built from the model's parameter
// values, with
//   static ParamTable params();               names, bounds, defaults (all Scope::Shared)
//   explicit X(const T* p);                   from parameter values in params() order
//   T D(const T& cos_theta) const;            normalized: ∫ D(ωm) cosθm dωm = 1, zero for cosθ ≤ 0
//   T P22(const T& x) const;                  slope-space form, x = tan²θ (where defined)
//   T unit(const T& cos_theta) const;         D/D(0), the peak-normalized shape (seed 001)
//   T Lambda(const T& tan_theta) const;       Smith Λ, only where a closed form exists
//   Vec3d sample(const Vec2d& u) const;       microfacet normal m with density D(m) cosθm
//   double pdf(const Vec3d& m) const;         = D(m) cosθm
#include <cmath>
#include <type_traits>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/param.h"

namespace brdfkit {

template <class T> struct Beckmann {
  T alpha;  // √2 × RMS slope

  static ParamTable params() {
    return {{"alpha", 1e-3, 2.0, 0.2, Scope::Shared, false, "Beckmann width, sqrt(2) x RMS slope (seed 000 Table 1)"}};
  }
  explicit Beckmann(const T* p) : alpha(p[0]) {}

  T P22(const T& x) const {
    using std::exp;
    const T a2 = alpha * alpha;
    return exp(-x / a2) / (T(kPi) * a2);
  }
  T D(const T& cos_theta) const {
    if (!(cos_theta > T(0))) return T(0);
    const T c2 = cos_theta * cos_theta;
    return P22((T(1) - c2) / c2) / (c2 * c2);
  }
  T unit(const T& cos_theta) const { return D(cos_theta) / D(T(1)); }
  // Closed form Λ (DESIGN.md §4), through erfc to avoid the cancellation of erf(a) − 1.
  T Lambda(const T& tan_theta) const {
    using std::erfc;
    using std::exp;
    if (!(tan_theta > T(0))) return T(0);
    const T a = T(1) / (alpha * tan_theta);
    return -erfc(a) / T(2) + exp(-a * a) / (T(2) * a * T(std::sqrt(kPi)));
  }

  // Inversion of the slope CDF: tan²θ = −α² ln(1 − u) (Walter et al. 2007, Eq. 28).
  Vec3d sample(const Vec2d& u) const
    requires std::is_same_v<T, double>
  {
    const double a = alpha;
    const double tan2 = -a * a * std::log1p(-u.x());
    const double cos_t = 1.0 / std::sqrt(1.0 + tan2);
    const double sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
    const double phi = 2 * kPi * u.y();
    return Vec3d(sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t);
  }
  double pdf(const Vec3d& m) const
    requires std::is_same_v<T, double>
  {
    return D(m.z()) * std::max(0.0, m.z());
  }
};

}  // namespace brdfkit
