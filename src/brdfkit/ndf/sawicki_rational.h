#pragma once
// Sawicki's rational distribution (Sawicki 2006, seed 001 Table 1, DESIGN.md §3):
//   D = 96 (3+N) cosθ / (π ((1−N) cosθ + N + 3)⁴),  D(0) = 3(3+N)/(8π).
// Sampling by a tabulated θ CDF (theta_cdf.h). Interface: ndf/distribution.h.
#include <cmath>
#include <optional>
#include <string_view>
#include <memory>
#include <type_traits>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/param.h"
#include "brdfkit/ndf/distribution.h"
#include "brdfkit/ndf/slope_space.h"
#include "brdfkit/ndf/theta_cdf.h"

namespace brdfkit {

template <class T> struct SawickiRational {
  static constexpr std::string_view kName = "sawicki-rational", kTitle = "Sawicki rational";
  // Seed 001's unit-form comparison (analysis/ndf_conversion.h).
  static constexpr UnitFormRange kUnitForm{"N_DS", 1e-3, 1e12,
                                           "Sawicki 2006, 256 cos b/((1-N)cos b+N+3)^4 (seed 001 Table 1)"};
  static constexpr std::string_view kHalfMaxRule = "Boost toms748 on D/D(0) = 1/2 / Eq. 10";
  // Seed 001 Eq. 10 with d = 1 − cos β: (4 (2(1 − d))^¼ + d − 4)/d; the numerator tends to
  // 4·2^¼ − 4, so only the denominator is small and it is exact.
  static std::optional<double> from_beta_half(double beta) {
    const double s = std::sin(beta / 2), d = 2 * s * s;
    return (4 * std::pow(2 * (1 - d), 0.25) + d - 4) / d;
  }
  T N;  // N_DS, sharpness

  static ParamTable params() {
    return {{"N", 0.0, 1e6, 50.0, Scope::Shared, false, "Sawicki rational sharpness N_DS (seed 001 Table 1)"}};
  }
  explicit SawickiRational(const T* p) : N(p[0]) {}

  T D(const T& cos_theta) const {
    if (!(cos_theta > T(0))) return T(0);
    const T q = (T(1) - N) * cos_theta + N + T(3);
    const T q2 = q * q;
    return T(96) * (T(3) + N) * cos_theta / (T(kPi) * q2 * q2);
  }
  // 256 cosθ / ((1−N) cosθ + N + 3)⁴ (seed 001 Table 1, unit form).
  T unit(const T& cos_theta) const {
    if (!(cos_theta > T(0))) return T(0);
    const T q = (T(1) - N) * cos_theta + N + T(3);
    const T q2 = q * q;
    return T(256) * cos_theta / (q2 * q2);
  }
  T P22(const T& x) const { return p22_from_d(*this, x); }

  Vec3d sample(const Vec2d& u) const
    requires std::is_same_v<T, double>
  {
    const SawickiRational self = *this;
    const ThetaCdf& cdf = cdf_->get([self] {
      return theta_cdf_of(self, kPi / 2);
    });
    return direction_from_theta(cdf.sample(u.x()), u.y());
  }
  double pdf(const Vec3d& m) const
    requires std::is_same_v<T, double>
  {
    return D(m.z()) * std::max(0.0, m.z());
  }

 private:
  std::shared_ptr<LazyThetaCdf> cdf_ = std::is_same_v<T, double> ? std::make_shared<LazyThetaCdf>() : nullptr;
};

// Smith Λ table coordinate N + 3 (log axis; N = 0 allowed, the width scales as 1/sqrt(N) for large N).
template <> struct SmithShape<SawickiRational> {
  static constexpr int kDims = 1;
  static std::vector<SmithAxis> axes() { return {{3.0, 1e6 + 3.0, 80, true}}; }
  template <class T> static std::array<T, 1> values(const SawickiRational<T>& d) { return {d.N + T(3)}; }
  static SawickiRational<double> make(const double* c) {
    const double n = c[0] - 3.0;
    return SawickiRational<double>(&n);
  }
};

}  // namespace brdfkit
