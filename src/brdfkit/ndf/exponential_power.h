#pragma once
// Exponential power distribution of seed 004 (Eq. 19, 26; DESIGN.md §3):
//   P22(x) = p/(π σ² Γ(1/p)) · exp(−(x/σ²)^p),  x = tan²θ.
// (Eq. 18 prints x/σ; Eq. 26 and the normalization ∫P22 dx = 1/π need x/σ².)
// Jets: Γ(1/p) carries its derivative through the digamma function. Interface: ndf/distribution.h.
#include <boost/math/special_functions/digamma.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <string_view>
#include <type_traits>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/param.h"
#include "brdfkit/ndf/distribution.h"
#include "brdfkit/ndf/d_block.h"
#include "brdfkit/core/scalar_chain.h"

namespace brdfkit {

template <class T> struct ExponentialPower {
  static constexpr std::string_view kName = "exponential-power", kTitle = "exponential power";
  T sigma;
  T p;
  T norm;  // p/(π σ² Γ(1/p))

  static ParamTable params() {
    return {{"sigma", 1e-4, 2.0, 0.1, Scope::Shared, false, "exponential power slope scale (seed 004 Eq. 19)"},
            {"p", 0.05, 10.0, 1.0, Scope::Shared, false, "exponential power shape; 1 is Beckmann (seed 004 Eq. 19)"}};
  }
  explicit ExponentialPower(const T* params) : sigma(params[0]), p(params[1]) {
    const double pv = value_of(p);
    const double g = boost::math::tgamma(1.0 / pv);
    // d/dp Γ(1/p) = −Γ(1/p) ψ(1/p) / p².
    const T gamma_inv_p = chain(g, -g * boost::math::digamma(1.0 / pv) / (pv * pv), p);
    norm = p / (T(kPi) * sigma * sigma * gamma_inv_p);
  }

  T P22(const T& x) const {
    using std::exp;
    using std::pow;
    if (!(x > T(0))) return norm;  // pow(0, p) has no finite p-derivative in Jets
    return norm * exp(-pow(x / (sigma * sigma), p));
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
    exponential_power_d_block(norm, sigma, p, c, out);
  }
  // P22 at the kP22Block slopes x[0 … kP22Block), for the Smith integral's nodes.
  void P22_block(const double* x, double* out) const
    requires std::is_same_v<T, double>
  {
    exponential_power_p22_block(norm, sigma, p, x, out);
  }
  T unit(const T& cos_theta) const { return D(cos_theta) / norm; }

  // With y = (x/σ²)^p the slope CDF is the regularized lower gamma P(1/p, y), so
  // tanθ = σ · Q⁻¹(1/p, 1−u)^{1/(2p)}. Seed 004 Eq. 23 prints the exponent p/2: wrong
  // (DESIGN.md §6; tests/ndf checks that the printed exponent fails the χ² test).
  Vec3d sample(const Vec2d& u) const
    requires std::is_same_v<T, double>
  {
    const double q = 1.0 - u.x();
    const double phi = 2 * kPi * u.y();
    if (!(q > 0.0)) return Vec3d(std::cos(phi), std::sin(phi), 0.0);
    const double y = boost::math::gamma_q_inv(1.0 / p, q);
    const double theta = std::atan(sigma * std::pow(y, 1.0 / (2.0 * p)));
    return Vec3d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  }
  double pdf(const Vec3d& m) const
    requires std::is_same_v<T, double>
  {
    return D(m.z()) * std::max(0.0, m.z());
  }
};

// Smith Λ table over (log σ, log p): along σ the table is exact up to the t½ shift (Λ depends on
// σ tanθ only, seed 004 §5.5).
template <> struct SmithShape<ExponentialPower> {
  static constexpr int kDims = 2;
  static std::vector<SmithAxis> axes() { return {{1e-4, 2.0, 6, true}, {0.05, 10.0, 140, true}}; }
  template <class T> static std::array<T, 2> values(const ExponentialPower<T>& d) { return {d.sigma, d.p}; }
};

}  // namespace brdfkit
