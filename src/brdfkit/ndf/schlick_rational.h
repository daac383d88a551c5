#pragma once
// Schlick's rational approximation of Beckmann (Schlick 1994c, as printed in seed 001 Table 1):
//   D = m³ x / (π cosθ (m x² − x² + m²)²),  x = cosθ + m − 1,
// defined only for cosθ ∈ [1−m, 1] (seed 001 §2) and zero outside, where it integrates to
// exactly 1: with y = x², 2π∫D cosθ dcosθ = m³ ∫₀^{m²} dy/((m−1)y + m²)² = 1.
// Interface: ndf/distribution.h.
#include <cmath>
#include <optional>
#include <string_view>
#include <limits>
#include <type_traits>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/param.h"
#include "brdfkit/ndf/distribution.h"
#include "brdfkit/ndf/slope_space.h"

namespace brdfkit {

template <class T> struct SchlickRational {
  static constexpr std::string_view kName = "schlick-rational", kTitle = "Schlick rational";
  // Seed 001's unit-form comparison (analysis/ndf_conversion.h): zero for cos β < 1 − m (§2.2).
  static constexpr UnitFormRange kUnitForm{
      "m_B", 1e-6, 1.0,
      "Schlick 1994, m^5 x/(cos b (m x^2-x^2+m^2)^2), x = cos b+m-1, zero for cos b < 1-m (seed 001 Table 1)"};
  T m;  // Beckmann's m_B, in (0, 1]

  static ParamTable params() {
    return {{"m", 1e-3, 1.0, 0.2, Scope::Shared, false, "Schlick rational width, approximates Beckmann m_B (seed 001 Table 1)"}};
  }
  explicit SchlickRational(const T* p) : m(p[0]) {}

  T D(const T& cos_theta) const {
    const T x = m - (T(1) - cos_theta);  // exact x = m at θ = 0
    if (!(x > T(0)) || !(cos_theta > T(0))) return T(0);
    const T q = m * x * x - x * x + m * m;
    return m * m * m * x / (T(kPi) * cos_theta * q * q);
  }
  // D(0) = 1/(π m²): D/D(0) = m⁵ x / (cosθ (m x² − x² + m²)²) (seed 001 Table 1, unit form).
  T unit(const T& cos_theta) const { return D(cos_theta) * T(kPi) * m * m; }
  T P22(const T& x) const { return p22_from_d(*this, x); }
  // Largest tan²θ of the support, cosθ_max = 1 − m: tan² = m(2 − m)/(1 − m)², unbounded at m ≥ 1.
  // smith_lambda_integral integrates up to this edge (shadowing/smith_integral.h).
  T tan2_max() const {
    if (!(m < T(1))) return T(std::numeric_limits<double>::infinity());
    const T c = T(1) - m;
    return m * (T(2) - m) / (c * c);
  }

  // Exact inversion: with y = x², P(X² ≤ y) = m y/((m−1) y + m²), so y = u m²/(m − u(m−1)).
  Vec3d sample(const Vec2d& u) const
    requires std::is_same_v<T, double>
  {
    const double y = u.x() * m * m / (m - u.x() * (m - 1.0));
    const double c = std::clamp(std::sqrt(std::max(0.0, y)) + 1.0 - m, 0.0, 1.0);
    return isotropic_normal(c, u.y());
  }
  double pdf(const Vec3d& mm) const
    requires std::is_same_v<T, double>
  {
    return D(mm.z()) * std::max(0.0, mm.z());
  }
};

// Smith Λ table with the support edge: no facet is steeper than tanθ_max, cosθ_max = 1 − m, so
// Λ = 0 for tanθ ≤ t_e = 1/tanθ_max = (1 − m)/sqrt(m(2 − m)), and near t_e Λ grows like
// (t − t_e)^{7/2} (P22 vanishes linearly at the edge), which the table's log(t − t_e) axis makes
// linear. At m = 1 the support becomes the whole hemisphere (D uniform, Λ ~ t²/4 at small t): the
// change of exponent moves towards t_e geometrically as 1 − m → 0, so the coordinate is
// q = m/(1 + δ − m) on a log axis, geometric in m for small m and in 1 + δ − m near 1.
template <> struct SmithShape<SchlickRational> {
  static constexpr int kDims = 1;
  static constexpr double kDelta = 1e-3;
  static std::vector<SmithAxis> axes() { return {{1e-3 / ((1 + kDelta) - 1e-3), 1.0 / ((1 + kDelta) - 1.0), 120, true}}; }
  template <class T> static std::array<T, 1> values(const SchlickRational<T>& d) { return {d.m / (T(1 + kDelta) - d.m)}; }
  template <class T> static T m_of(const T& q) { return q * T(1 + kDelta) / (T(1) + q); }
  static SchlickRational<double> make(const double* c) {
    const double m = m_of(c[0]);
    return SchlickRational<double>(&m);
  }
  template <class T> static T tan_edge(const T* c) {
    using std::sqrt;
    const T m = m_of(c[0]);
    if (!(m < T(1))) return T(0);
    return (T(1) - m) / sqrt(m * (T(2) - m));
  }
};

}  // namespace brdfkit
