#pragma once
// Exponential distribution: P22(x) = exp(−sqrt(x/α²)) / (2π α²), x = tan²θ
// (seed 000 Table 1, DESIGN.md §3). Interface: ndf/distribution.h.
#include <boost/math/special_functions/lambert_w.hpp>
#include <cmath>
#include <optional>
#include <string_view>
#include <type_traits>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/param.h"
#include "brdfkit/ndf/distribution.h"
#include "brdfkit/ndf/d_block.h"

namespace brdfkit {

template <class T> struct Exponential {
  static constexpr std::string_view kName = "exponential", kTitle = "exponential";
  // Seed 001's unit-form comparison (analysis/ndf_conversion.h): exp(−tanβ/α)/cos⁴β rises again
  // beyond tanβ = 1 for α > ½.
  static constexpr UnitFormRange kUnitForm{"alpha", 1e-6, 0.5, "exponential, exp(-tan b/alpha)/cos^4 b (seed 000 Table 1)"};
  T alpha;

  static ParamTable params() {
    return {{"alpha", 1e-3, 2.0, 0.2, Scope::Shared, false, "exponential distribution width (seed 000 Table 1)"}};
  }
  explicit Exponential(const T* p) : alpha(p[0]) {}

  T P22(const T& x) const {
    using std::exp;
    using std::sqrt;
    if (!(x > T(0))) return T(1) / (T(2 * kPi) * alpha * alpha);  // sqrt's Jet derivative is 0/0 at 0
    return exp(-sqrt(x) / alpha) / (T(2 * kPi) * alpha * alpha);
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
    exponential_d_block(alpha, c, out);
  }
  T unit(const T& cos_theta) const { return D(cos_theta) / D(T(1)); }

  // With s = tanθ/α the slope CDF is 1 − (1+s)e⁻ˢ (the Gamma(2) CDF): (1+s)e⁻ˢ = 1−u = q
  // inverts through the lower Lambert branch, s = −1 − W₋₁(−q/e).
  Vec3d sample(const Vec2d& u) const
    requires std::is_same_v<T, double>
  {
    const double q = 1.0 - u.x();  // u = 1 would be s = ∞ (θ = π/2)
    const double s = q > 0.0 ? -1.0 - boost::math::lambert_wm1(-q * std::exp(-1.0)) : 1e300;
    const double theta = std::atan(alpha * s);
    const double phi = 2 * kPi * u.y();
    return Vec3d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  }
  double pdf(const Vec3d& m) const
    requires std::is_same_v<T, double>
  {
    return D(m.z()) * std::max(0.0, m.z());
  }
};

// Smith Λ table over log α (a scale family: exact up to the t½ shift).
template <> struct SmithShape<Exponential> {
  static constexpr int kDims = 1;
  static std::vector<SmithAxis> axes() { return {{1e-3, 2.0, 8, true}}; }
  template <class T> static std::array<T, 1> values(const Exponential<T>& d) { return {d.alpha}; }
};

}  // namespace brdfkit
