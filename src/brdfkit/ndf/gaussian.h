#pragma once
// Gaussian (Torrance-Sparrow) distribution: D = k(m) exp(−θ²/m²) (seed 001 Table 1, DESIGN.md §3),
// normalized numerically: k = 1/(2π I(m)), I(m) = ∫₀^{π/2} e^{−θ²/m²} cosθ sinθ dθ by
// Gauss-Kronrod. Seed 001 prints k ≈ (2 ln cos β½ − ln 2)/(2π ln cos β½), β½ = m sqrt(ln 2):
// an approximation, not the normalization (tests/ndf measures how far it is).
// Jets: ∂I/∂m = ∫ e^{−θ²/m²} (2θ²/m³) cosθ sinθ dθ by the same quadrature, exact to rounding.
// Sampling by a tabulated θ CDF (theta_cdf.h). Interface: ndf/distribution.h.
#include <cmath>
#include <optional>
#include <string_view>
#include <memory>
#include <type_traits>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/param.h"
#include "brdfkit/ndf/distribution.h"
#include "brdfkit/ndf/d_block.h"
#include "brdfkit/ndf/slope_space.h"
#include "brdfkit/core/scalar_chain.h"
#include "brdfkit/ndf/theta_cdf.h"

namespace brdfkit {

// I(m) and dI/dm; memoized per thread on the last m, since fits construct the distribution
// for every evaluation with the same m.
double gaussian_ndf_integral(double m, double* dI_dm = nullptr);
// Tabulated θ CDF of 2π D cosθ sinθ for width m.
ThetaCdf gaussian_ndf_cdf(double m);

template <class T> struct Gaussian {
  static constexpr std::string_view kName = "gaussian", kTitle = "Gaussian";
  // Seed 001's unit-form comparison (analysis/ndf_conversion.h). The unit form needs no
  // normalization (the constructor's quadrature would cost 200× a whole conversion).
  static constexpr UnitFormRange kUnitForm{"m_G", 1e-6, 4.0,
                                           "Gaussian (Torrance-Sparrow), exp(-b^2/m_G^2) (seed 001 Table 1)"};
  static constexpr std::string_view kHalfMaxRule = "Eq. 7/4";
  static double unit_form(double m, double cos_beta) {
    const double beta = std::acos(cos_beta);
    return std::exp(-beta * beta / (m * m));
  }
  // Seed 001 Eq. 7 and Eq. 4.
  static std::optional<double> beta_half(double m) {
    const double b = m * std::sqrt(std::log(2.0));
    if (b >= kPi / 2) return std::nullopt;
    return b;
  }
  static std::optional<double> from_beta_half(double beta) { return beta / std::sqrt(std::log(2.0)); }
  T m;     // angular width in radians (C_TS = 1/m in seed 001)
  T norm;  // k(m)

  static ParamTable params() {
    return {{"m", 1e-3, 1.5, 0.2, Scope::Shared, false, "Gaussian angular width in radians (seed 001 Table 1, m_G)"}};
  }
  explicit Gaussian(const T* p) : m(p[0]) {
    double dI = 0.0;
    const double I = gaussian_ndf_integral(value_of(m), &dI);
    norm = T(1) / (T(2 * kPi) * chain(I, dI, m));
  }

  T unit(const T& cos_theta) const {
    using std::acos;
    using std::exp;
    if (!(cos_theta > T(0))) return T(0);
    if (!(cos_theta < T(1))) return T(1);  // acos' Jet derivative is 0/0 at 1
    const T theta = acos(cos_theta);
    return exp(-theta * theta / (m * m));
  }
  T D(const T& cos_theta) const { return norm * unit(cos_theta); }
  // D at the kDBlock cosines c[0 … kDBlock) (ndf/d_block.h), for the batch loops.
  void D_block(const double* c, double* out) const
    requires std::is_same_v<T, double>
  {
    gaussian_d_block(norm, m, c, out);
  }
  T P22(const T& x) const { return p22_from_d(*this, x); }
  // P22 at the kP22Block slopes x[0 … kP22Block), for the Smith integral's nodes.
  void P22_block(const double* x, double* out) const
    requires std::is_same_v<T, double>
  {
    gaussian_p22_block(norm, m, x, out);
  }

  Vec3d sample(const Vec2d& u) const
    requires std::is_same_v<T, double>
  {
    const double mv = m;
    return direction_from_theta(cdf_->get([mv] { return gaussian_ndf_cdf(mv); }).sample(u.x()), u.y());
  }
  double pdf(const Vec3d& mm) const
    requires std::is_same_v<T, double>
  {
    return D(mm.z()) * std::max(0.0, mm.z());
  }

 private:
  std::shared_ptr<LazyThetaCdf> cdf_ = std::is_same_v<T, double> ? std::make_shared<LazyThetaCdf>() : nullptr;
};

// Smith Λ table over log m (for small m the distribution is Beckmann-like, a scale family).
template <> struct SmithShape<Gaussian> {
  static constexpr int kDims = 1;
  static std::vector<SmithAxis> axes() { return {{1e-3, 1.5, 120, true}}; }
  template <class T> static std::array<T, 1> values(const Gaussian<T>& d) { return {d.m}; }
};

}  // namespace brdfkit
