#pragma once
// Generalized Trowbridge-Reitz (Burley 2012), seed 004 Table 1, DESIGN.md §3:
//   γ ≠ 1: P22 = (γ−1)(1−α²)/(1−α^{2(γ−1)}) · α^{2(γ−1)} (1+x)^{γ−2} / (π (α²+x)^γ)
//   γ = 1: P22 = (1−α²)/(2π ln(1/α)) · 1/((1+x)(α²+x))
// In cosθ, with s = 1 + (α²−1) cos²θ = (α²+x) cos²θ: D = c_γ α^{2(γ−1)} / (π s^γ).
// Both branches are one expression: with L = ln α² and t = (γ−1) L,
//   c_γ = (1−α²)/(−L) · t/(eᵗ − 1),
// and t/(eᵗ−1) → 1 as γ → 1 gives the γ = 1 constant; evaluating t/expm1(t) by its series
// near t = 0 keeps D and its γ-derivative smooth across γ = 1 (Jets included).
// γ = 2 is GGX. Interface: ndf/distribution.h.
#include <cmath>
#include <string_view>
#include <type_traits>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/param.h"
#include "brdfkit/ndf/distribution.h"
#include "brdfkit/ndf/d_block.h"

namespace brdfkit {

template <class T> struct Gtr {
  static constexpr std::string_view kName = "gtr", kTitle = "GTR";
  T alpha;
  T gamma;
  T norm;  // c_γ α^{2(γ−1)} / π

  static ParamTable params() {
    return {{"alpha", 1e-3, 2.0, 0.2, Scope::Shared, false, "GTR width, C_TR of seed 001 (seed 004 Table 1)"},
            {"gamma", 0.1, 10.0, 2.0, Scope::Shared, false, "GTR tail exponent; 2 is GGX, 1 is Berry (seed 004 Table 1)"}};
  }
  explicit Gtr(const T* p) : alpha(p[0]), gamma(p[1]) {
    using std::exp;
    using std::expm1;
    using std::log;
    const T a2 = alpha * alpha;
    const T L = log(a2);
    const T t = (gamma - T(1)) * L;
    // t/(eᵗ−1) = 1 − t/2 + t²/12 − t⁴/720 + …, Bernoulli series; error < 1e-19 for |t| < 1e-3.
    const T bern = abs_less(t, 1e-3) ? T(1) - t / T(2) + t * t / T(12) - t * t * t * t / T(720) : t / expm1(t);
    // (1−α²)/(−ln α²) → 1 as α → 1: with u = 1−α², u/(−ln(1−u)) = 1/(1 + u/2 + u²/3 + u³/4 + …).
    const T u = T(1) - a2;
    const T lead = abs_less(u, 1e-4) ? T(1) / (T(1) + u / T(2) + u * u / T(3) + u * u * u / T(4)) : u / (-L);
    norm = lead * bern * exp(t) / T(kPi);
  }

  T D(const T& cos_theta) const {
    using std::pow;
    if (!(cos_theta > T(0))) return T(0);
    return norm / pow(denom(cos_theta), gamma);
  }
  // D at the kDBlock cosines c[0 … kDBlock) (ndf/d_block.h), for the batch loops.
  void D_block(const double* c, double* out) const
    requires std::is_same_v<T, double>
  {
    gtr_d_block(norm, alpha, gamma, c, out);
  }
  // P22 at the kP22Block slopes x[0 … kP22Block), for the Smith integral's nodes.
  void P22_block(const double* x, double* out) const
    requires std::is_same_v<T, double>
  {
    gtr_p22_block(norm, alpha, gamma, x, out);
  }
  T P22(const T& x) const {
    const T c2 = T(1) / (T(1) + x);
    using std::sqrt;
    return D(sqrt(c2)) * c2 * c2;
  }
  // D/D(0) = (α²/s)^γ (seed 001 Table 1, unit form).
  T unit(const T& cos_theta) const {
    using std::pow;
    if (!(cos_theta > T(0))) return T(0);
    return pow(alpha * alpha / denom(cos_theta), gamma);
  }

  // Inversion in v = cos²θ: P(V ≥ v) = (α^{2(1−γ)} − s^{1−γ})/(α^{2(1−γ)} − 1), so
  // s^{1−γ} = α^{2(1−γ)}(1−u) + u, and s = α^{2(1−u)} at γ = 1 (Burley 2012, App. B).
  Vec3d sample(const Vec2d& u) const
    requires std::is_same_v<T, double>
  {
    const double a2 = alpha * alpha, L = std::log(a2), g1 = 1.0 - gamma;
    double log_s;
    if (std::abs(g1) < 1e-7) {
      log_s = L * (1.0 - u.x());
    } else {
      // ln(e^{w}(1−u) + u) with w = (1−γ)L, without overflowing e^{w}.
      const double w = g1 * L;
      const double m = std::max(w, 0.0);
      log_s = (m + std::log(std::exp(w - m) * (1.0 - u.x()) + std::exp(-m) * u.x())) / g1;
    }
    const double v = std::abs(a2 - 1.0) < 1e-12 ? u.x() : std::expm1(log_s) / (a2 - 1.0);
    const double c = std::sqrt(std::clamp(v, 0.0, 1.0));
    return isotropic_normal(c, u.y());
  }
  double pdf(const Vec3d& m) const
    requires std::is_same_v<T, double>
  {
    return D(m.z()) * std::max(0.0, m.z());
  }

 private:
  // s = 1 + (α²−1) cos²θ written as α² cos²θ + (1−c)(1+c): exact at θ = 0 for tiny α.
  T denom(const T& c) const { return alpha * alpha * c * c + (T(1) - c) * (T(1) + c); }
  static bool abs_less(const T& x, double bound) { return x < T(bound) && x > T(-bound); }
};

// Smith Λ table over (log α, γ). Near α = 1 the shape changes as γ(1 − α²) (at α = 1 every γ is
// the uniform distribution), fast at large γ: the α axis is fine, which costs nothing at start-up
// since table nodes are integrated lazily (shadowing/smith_table.h).
template <> struct SmithShape<Gtr> {
  static constexpr int kDims = 2;
  static std::vector<SmithAxis> axes() { return {{1e-3, 2.0, 400, true}, {0.1, 10.0, 400, false}}; }
  template <class T> static std::array<T, 2> values(const Gtr<T>& d) { return {d.alpha, d.gamma}; }
};

}  // namespace brdfkit
