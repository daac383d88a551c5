#pragma once
// Blinn-Phong distribution: D = (N+2)/(2π) cosᴺθ (seed 001 Table 1, DESIGN.md §3).
// Interface: ndf/distribution.h.
#include <cmath>
#include <optional>
#include <string_view>
#include <type_traits>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/param.h"
#include "brdfkit/ndf/distribution.h"
#include "brdfkit/ndf/d_block.h"

namespace brdfkit {

template <class T> struct BlinnPhong {
  static constexpr std::string_view kName = "blinn-phong", kTitle = "Blinn-Phong";
  // Seed 001's unit-form comparison (analysis/ndf_conversion.h).
  static constexpr UnitFormRange kUnitForm{"N", 0.1, 1e12, "Blinn-Phong, cos^N b (seed 001 Table 1)"};
  static constexpr std::string_view kHalfMaxRule = "Eq. 6/3";
  // Seed 001 Eq. 6, cos β = 2^(−1/N), as 2 asin(sqrt((1 − cos β)/2)): exact for N up to 1e12.
  static std::optional<double> beta_half(double n) {
    return 2 * std::asin(std::sqrt(-std::expm1(-std::log(2.0) / n) / 2));
  }
  // Seed 001 Eq. 3, ln cos β through log1p.
  static std::optional<double> from_beta_half(double beta) {
    const double s = std::sin(beta / 2);
    return -std::log(2.0) / std::log1p(-2 * s * s);
  }
  T N;  // exponent (sharpness)

  static ParamTable params() {
    return {{"N", 0.0, 1e6, 50.0, Scope::Shared, false, "Blinn-Phong exponent (seed 001 Table 1)"}};
  }
  explicit BlinnPhong(const T* p) : N(p[0]) {}

  // P22 = D cos⁴θ with cos²θ = 1/(1+x): (N+2)/(2π) (1+x)^{−(N+4)/2}.
  T P22(const T& x) const {
    using std::pow;
    return (N + T(2)) / T(2 * kPi) * pow(T(1) + x, -(N + T(4)) / T(2));
  }
  T D(const T& cos_theta) const {
    if (!(cos_theta > T(0))) return T(0);
    return (N + T(2)) / T(2 * kPi) * unit(cos_theta);
  }
  // D at the kDBlock cosines c[0 … kDBlock) (ndf/d_block.h), for the batch loops.
  void D_block(const double* c, double* out) const
    requires std::is_same_v<T, double>
  {
    blinn_phong_d_block(N, c, out);
  }
  T unit(const T& cos_theta) const {
    using std::pow;
    if (!(cos_theta > T(0))) return T(0);
    return pow(cos_theta, N);
  }

  // pdf of c = cosθ is (N+2) c^{N+1}, CDF c^{N+2}: c = u^{1/(N+2)}.
  Vec3d sample(const Vec2d& u) const
    requires std::is_same_v<T, double>
  {
    const double c = u.x() > 0.0 ? std::exp(std::log(u.x()) / (N + 2.0)) : 0.0;
    return isotropic_normal(c, u.y());
  }
  double pdf(const Vec3d& m) const
    requires std::is_same_v<T, double>
  {
    return D(m.z()) * std::max(0.0, m.z());
  }
};

// Smith Λ table coordinate N + 2 (log axis): N = 0 is allowed, and for large N cosᴺ tends to a
// Beckmann shape of width sqrt(2/(N+2)), a scale family, which the table's t½ shift makes flat.
template <> struct SmithShape<BlinnPhong> {
  static constexpr int kDims = 1;
  static std::vector<SmithAxis> axes() { return {{2.0, 1e6 + 2.0, 100, true}}; }
  template <class T> static std::array<T, 1> values(const BlinnPhong<T>& d) { return {d.N + T(2)}; }
  static BlinnPhong<double> make(const double* c) {
    const double n = c[0] - 2.0;
    return BlinnPhong<double>(&n);
  }
};

}  // namespace brdfkit
