#pragma once
// Trowbridge-Reitz / GGX distribution: P22(x) = α² / (π (α² + x)²), x = tan²θ
// (seed 000 Table 1, DESIGN.md §3). Interface: ndf/distribution.h.
#include <cmath>
#include <optional>
#include <string_view>
#include <type_traits>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/param.h"
#include "brdfkit/ndf/distribution.h"

namespace brdfkit {

template <class T> struct Ggx {
  static constexpr std::string_view kName = "ggx", kTitle = "GGX";
  // Seed 001's unit-form comparison (analysis/ndf_conversion.h).
  static constexpr UnitFormRange kUnitForm{"C_TR", 1e-6, 1.0,
                                           "Trowbridge-Reitz / GGX, [C^2/(cos^2 b (C^2-1)+1)]^2 (seed 001 Table 1)"};
  static constexpr std::string_view kHalfMaxRule = "Eq. 8/5";
  // Seed 001 Eq. 8 as sin²β = C²(√2 − 1)/(1 − C²): no cancellation for small C. The shape stays
  // above ½ (D(π/2)/D(0) = C⁴) for C ≥ 2^(−1/4).
  static std::optional<double> beta_half(double c) {
    const double s2 = c * c * (std::sqrt(2.0) - 1) / (1 - c * c);
    if (!(s2 < 1)) return std::nullopt;
    return std::asin(std::sqrt(s2));
  }
  // Seed 001 Eq. 5 as C² = sin²β/(√2 − 1 + sin²β).
  static std::optional<double> from_beta_half(double beta) {
    const double s2 = std::sin(beta) * std::sin(beta);
    return std::sqrt(s2 / (std::sqrt(2.0) - 1 + s2));
  }
  T alpha;  // Sawicki's C_TR; Disney roughness r maps to α = r² (DESIGN.md §3)
  // Its closed-form Λ (one square root) is cheaper than a G1 row (models/cook_torrance.h).
  static constexpr bool kCheapLambda = true;

  static ParamTable params() {
    return {{"alpha", 1e-3, 2.0, 0.2, Scope::Shared, false, "GGX / Trowbridge-Reitz width C_TR (seed 000 Table 1)"}};
  }
  explicit Ggx(const T* p) : alpha(p[0]) {}

  T P22(const T& x) const {
    const T a2 = alpha * alpha;
    const T s = a2 + x;
    return a2 / (T(kPi) * s * s);
  }
  // Written in cos²θ directly: α² / (π (cos²θ (α² − 1) + 1)²), no tan² blow-up at grazing angles;
  // the denominator as α² cos²θ + sin²θ, sin²θ = (1−c)(1+c), is exact at θ = 0 for tiny α.
  static T denom(const T& a2, const T& c) { return a2 * c * c + (T(1) - c) * (T(1) + c); }
  T D(const T& cos_theta) const {
    if (!(cos_theta > T(0))) return T(0);
    const T a2 = alpha * alpha;
    const T s = denom(a2, cos_theta);
    return a2 / (T(kPi) * s * s);
  }
  // D/D(0) = α⁴ / (cos²θ (α² − 1) + 1)², the peak-normalized shape of seed 001 Table 1.
  T unit(const T& cos_theta) const {
    if (!(cos_theta > T(0))) return T(0);
    const T a2 = alpha * alpha;
    const T s = denom(a2, cos_theta);
    return a2 * a2 / (s * s);
  }
  // Closed-form Λ = (sqrt(1 + α² tan²θ) − 1)/2 (DESIGN.md §4).
  T Lambda(const T& tan_theta) const {
    using std::sqrt;
    if (!(tan_theta > T(0))) return T(0);
    const T at = alpha * tan_theta;
    // (sqrt(1+y) − 1)/2 = y / (2 (sqrt(1+y) + 1)): no cancellation for small α tanθ.
    const T y = at * at;
    return y / (T(2) * (sqrt(T(1) + y) + T(1)));
  }

  // Inversion of the slope CDF F(x) = x/(α² + x): tan²θ = α² u/(1 − u) (Walter et al. 2007, Eq. 35).
  Vec3d sample(const Vec2d& u) const
    requires std::is_same_v<T, double>
  {
    const double a2 = alpha * alpha;
    // cos²θ = (1 − u)/(1 + (α² − 1) u), avoids the u → 1 division.
    const double cos2 = (1.0 - u.x()) / (1.0 + (a2 - 1.0) * u.x());
    return isotropic_normal(std::sqrt(std::clamp(cos2, 0.0, 1.0)), u.y());
  }
  double pdf(const Vec3d& m) const
    requires std::is_same_v<T, double>
  {
    return D(m.z()) * std::max(0.0, m.z());
  }
};

}  // namespace brdfkit
