#pragma once
// Tabulated distribution (seed 002 §5.1, DESIGN.md §3): D given at angles θ₀ < θ₁ < … ≤ π/2,
// linear in θ between nodes, zero beyond the last node, constant D(θ₀) below the first; the
// values are rescaled so that ∫ D cosθ dω = 1. That integral is exact per cell:
//   ∫ (a + bθ) cosθ sinθ dθ = a sin²θ/2 + b (sin2θ/8 − θ cos2θ/4),
// so the normalization is linear in the values and Jets carry it. Sampling by a tabulated θ CDF
// (theta_cdf.h). params() is empty: the values are not named parameters.
// Interface: ndf/distribution.h.
#include <algorithm>
#include <cmath>
#include <string_view>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "brdfkit/core/error.h"
#include "brdfkit/core/vec.h"
#include "brdfkit/core/param.h"
#include "brdfkit/ndf/distribution.h"
#include "brdfkit/ndf/slope_space.h"
#include "brdfkit/core/scalar_chain.h"
#include "brdfkit/ndf/theta_cdf.h"

namespace brdfkit {

template <class T> struct Tabulated {
  static constexpr std::string_view kName = "tabulated", kTitle = "tabulated";
  std::vector<double> theta;  // nodes, radians, increasing
  std::vector<T> value;       // normalized D at the nodes

  static ParamTable params() { return {}; }

  // Throws InputError (naming the node) for fewer than 2 nodes, non-increasing or out-of-range
  // angles, negative or non-finite values, or an all-zero table.
  Tabulated(std::vector<double> theta_nodes, std::vector<T> d_values) : theta(std::move(theta_nodes)), value(std::move(d_values)) {
    const std::string where = "tabulated distribution";
    if (theta.size() < 2) throw InputError(where, "needs at least 2 angles, got " + std::to_string(theta.size()));
    if (theta.size() != value.size())
      throw InputError(where, std::to_string(theta.size()) + " angles but " + std::to_string(value.size()) + " values");
    for (std::size_t i = 0; i < theta.size(); ++i) {
      if (!(theta[i] >= 0.0 && theta[i] <= kPi / 2))
        throw InputError(where, "angle " + std::to_string(i) + " = " + std::to_string(theta[i]) + " is outside [0, pi/2]");
      if (i > 0 && !(theta[i] > theta[i - 1]))
        throw InputError(where, "angles must increase (angle " + std::to_string(i) + ")");
      const double v = value_of(value[i]);
      if (!(v >= 0.0) || !std::isfinite(v))
        throw InputError(where, "value " + std::to_string(i) + " = " + std::to_string(v) + " must be finite and >= 0");
    }
    const T mass = raw_mass();
    if (!(mass > T(0))) throw InputError(where, "all values are zero");
    for (auto& v : value) v = v / mass;
  }

  T D(const T& cos_theta) const {
    using std::acos;
    if (!(cos_theta > T(0))) return T(0);
    const T t = cos_theta < T(1) ? acos(cos_theta) : T(0);  // acos' Jet derivative is 0/0 at 1
    const double tv = value_of(t);
    if (tv <= theta.front()) return value.front();
    if (tv > theta.back()) return T(0);
    const std::size_t i = std::size_t(std::upper_bound(theta.begin(), theta.end(), tv) - theta.begin()) - 1;
    if (i + 1 >= theta.size()) return value.back();
    const T w = (t - T(theta[i])) / T(theta[i + 1] - theta[i]);
    return value[i] + w * (value[i + 1] - value[i]);
  }
  T unit(const T& cos_theta) const { return D(cos_theta) / D(T(1)); }
  T P22(const T& x) const { return p22_from_d(*this, x); }

  Vec3d sample(const Vec2d& u) const
    requires std::is_same_v<T, double>
  {
    const Tabulated& self = *this;
    const ThetaCdf& cdf = cdf_->get([&self] {
      return theta_cdf_of(self, self.theta.back());
    });
    return direction_from_theta(cdf.sample(u.x()), u.y());
  }
  double pdf(const Vec3d& m) const
    requires std::is_same_v<T, double>
  {
    return D(m.z()) * std::max(0.0, m.z());
  }

 private:
  // ∫ D cosθ dω of the piecewise-linear table (exact per cell, header comment).
  T raw_mass() const {
    auto F0 = [](double t) { return 0.5 * std::sin(t) * std::sin(t); };                       // ∫ cos sin
    auto F1 = [](double t) { return std::sin(2 * t) / 8 - t * std::cos(2 * t) / 4; };         // ∫ θ cos sin
    T mass = value.front() * T(F0(theta.front()));                                             // constant below θ₀
    for (std::size_t i = 0; i + 1 < theta.size(); ++i) {
      const double t0 = theta[i], t1 = theta[i + 1], h = t1 - t0;
      const T b = (value[i + 1] - value[i]) / T(h);
      const T a = value[i] - b * T(t0);
      mass += a * T(F0(t1) - F0(t0)) + b * T(F1(t1) - F1(t0));
    }
    return T(2 * kPi) * mass;
  }

  std::shared_ptr<LazyThetaCdf> cdf_ = std::is_same_v<T, double> ? std::make_shared<LazyThetaCdf>() : nullptr;
};

}  // namespace brdfkit
