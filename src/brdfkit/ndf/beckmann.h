#pragma once
// Beckmann distribution: P22(x) = exp(−x/α²)/(π α²), x = tan²θ (seed 000 Table 1, DESIGN.md §3).
//
// Interface: ndf/distribution.h.
#include <cmath>
#include <optional>
#include <string_view>
#include <type_traits>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/param.h"
#include "brdfkit/ndf/d_block.h"
#include "brdfkit/ndf/distribution.h"

namespace brdfkit {

template <class T> struct Beckmann {
  static constexpr std::string_view kName = "beckmann", kTitle = "Beckmann";
  // Seed 001's unit-form comparison (analysis/ndf_conversion.h): (1+x)² e^{−x/α²} (x = tan²β) rises at
  // β = 0 for α > 1/√2.
  static constexpr UnitFormRange kUnitForm{"m_B", 1e-6, 0.70710678118654752,
                                           "Beckmann, exp(-tan^2 b/m_B^2)/cos^4 b (seed 001 Table 1)"};
  static constexpr std::string_view kHalfMaxRule = "Boost toms748 on D/D(0) = 1/2 / Eq. 9";
  // Seed 001 Eq. 9: the α whose unit form falls to ½ at β; ln cos β through log1p for small β.
  static std::optional<double> from_beta_half(double beta) {
    const double s = std::sin(beta / 2);
    return std::tan(beta) / std::sqrt(std::log(2.0) - 4 * std::log1p(-2 * s * s));
  }
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
  // D at the kDBlock cosines c[0 … kDBlock) (ndf/d_block.h), for the batch loops.
  void D_block(const double* c, double* out) const
    requires std::is_same_v<T, double>
  {
    beckmann_d_block(alpha, c, out);
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
    return isotropic_normal(1.0 / std::sqrt(1.0 + tan2), u.y());
  }
  double pdf(const Vec3d& m) const
    requires std::is_same_v<T, double>
  {
    return D(m.z()) * std::max(0.0, m.z());
  }
};

}  // namespace brdfkit
