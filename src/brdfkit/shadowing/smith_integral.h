#pragma once
// Smith Λ of any distribution by direct numerical integration of its slope density P22
// (seed 000 Eq. 6, seed 004 Eq. 4–7, DESIGN.md §4), templated on the scalar so ceres::Jet
// parameters and tanθ carry derivatives through P22 and through the kernel.
//
// DESIGN.md §4 writes Λ as two nested integrals: P2(r) = ∫ P22(r² + q²) dq over ℝ and
// Λ(t) = ∫_{1/t}^∞ (r t − 1) P2(r) dr, t = tanθ. In polar slope coordinates (ρ, φ), r = ρ cos φ,
// the φ integral has a closed form, ∫_{ρ cosφ > 1/t} (ρ t cosφ − 1) dφ = 2(sqrt(ρ²t² − 1) − acos(1/(ρt))),
// which leaves one integral. With ρ² = (1 + s²)/t² (so s = sqrt(ρ²t² − 1) and acos(1/(ρt)) = atan s):
//   Λ(t) = (2/t²) ∫₀^∞ P22((1 + s²)/t²) · s (s − atan s) ds.
// tests/shadowing checks it against the nested form with Boost quadrature and the closed forms.
//
// Quadrature: s = e^w turns every feature of the integrand into one of width O(1) in w, whatever
// the distribution's width, so a composite Gauss-Legendre rule (Boost's nodes) on panels of width
// ½ in w is accurate to ~1e-10 for smooth P22: 7 points per panel and panels down to 1e-14 of the
// integrand's peak agree with 10 points and 1e-20 to 1.5e-10 relative (GTR, GGX, Beckmann,
// exponential power over α, their shapes and 48 tanθ, the worst at exponential power p = 1.9) at
// half the cost, and this integral is what a lazily built Smith table node costs (shadowing/
// smith_table.h). A scan over a wide w range finds where the integrand lives; panels where it is
// negligible are skipped (shadowing/log_panel_quadrature.h). The window's ends are whole panels,
// so the panels of every tanθ lie on one lattice: distributions with a vector P22 take the other
// factors at its points from a table (shadowing/smith_lattice_panels.h).
//
// Compact support (Schlick's rational distribution vanishes beyond tan²θ = x_max, and x_max moves
// with its parameter): the integrand stops at s_max = sqrt(t² x_max − 1), with a kink there. Fixed
// panels in w would put that kink inside a panel whose rule does not see the edge move, so the Jet
// derivative missed the edge's motion (1e-4 relative in ∂/∂m). Instead the integral is
// reparametrized to a fixed domain, s = s_max e^u with u ≤ 0: the panels end exactly at the edge
// for every parameter value, and Jets differentiate through s_max (the Leibniz boundary term is
// carried by the substitution; it is zero here anyway since P22 → 0 at the edge).
// A distribution opts in by providing `T tan2_max() const` (x_max, +∞ when unbounded).
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "brdfkit/shadowing/log_panel_quadrature.h"
#include "brdfkit/shadowing/smith_lattice_panels.h"

namespace brdfkit {

namespace smith_detail {

// s − atan s without cancellation for small s (Taylor series, error < s¹¹/11), for doubles and Jets.
template <class T> T s_minus_atan(const T& s) {
  using std::atan;
  if (scalar(s) < 1e-2) {
    const T s2 = s * s;
    return s * s2 * (T(1.0 / 3) - s2 * (T(1.0 / 5) - s2 * (T(1.0 / 7) - s2 / T(9))));
  }
  return s - atan(s);
}

}  // namespace smith_detail

// Λ(tanθ) from ndf.P22 (any type with `U P22(const U& x) const`, U = T).
template <class Ndf, class T> T smith_lambda_integral(const Ndf& ndf, const T& tan_theta) {
  namespace sd = smith_detail;
  const double t0 = sd::scalar(tan_theta);
  if (!(t0 > 0.0)) return T(0);
  if (!std::isfinite(t0)) return T(std::numeric_limits<double>::infinity());  // grazing: G1 = 0
  const T inv_t2 = T(1) / (tan_theta * tan_theta);
  // The features sit near s ~ 1 and s ~ (distribution width)·t; the scan window follows t.
  const double lt = std::log(t0);
  const double w_lo = -30.0 + std::min(0.0, lt), w_hi = 45.0 + std::max(0.0, lt);
  if constexpr (requires { ndf.tan2_max(); }) {
    const T x_max = ndf.tan2_max();
    const double xm = sd::scalar(x_max);
    if (std::isfinite(xm)) {
      // Slopes r < 1/t mask nothing: the support must reach beyond them.
      if (!(t0 * t0 * xm > 1.0)) return T(0);
      using std::sqrt;
      const T s_max = sqrt(tan_theta * tan_theta * x_max - T(1));
      // In u = log(s/s_max) ≤ 0 (ds = s du), with s a T so that Jets see the edge move.
      auto g = [&](double u) -> T {
        const T s = s_max * T(std::exp(u));
        const T x = (T(1) + s * s) * inv_t2;
        return ndf.P22(x) * s * s * sd::s_minus_atan(s);
      };
      const double u_lo = std::min(-1.0, w_lo - std::log(sd::scalar(s_max)));
      return T(2) * inv_t2 * sd::integrate_log_panels<T>(g, u_lo, 0.0);
    }
  }
  // The window widened to whole panels, so that every integral's panels lie on one lattice in w
  // (smith_lattice_panels.h).
  const int i_lo = static_cast<int>(std::floor(w_lo / sd::kPanelWidth));
  const int i_hi = static_cast<int>(std::ceil(w_hi / sd::kPanelWidth));
  // Integrand in w = log s, including the Jacobian ds = s dw.
  if constexpr (std::is_same_v<T, double> && sd::HasP22Block<Ndf>) {
    return 2.0 * inv_t2 * sd::integrate_lattice_panels(ndf, inv_t2, i_lo, i_hi);
  }
  auto g = [&](double w) -> T {
    const double s = std::exp(w);
    const T x = (T(1) + T(s * s)) * inv_t2;
    return ndf.P22(x) * T(s * s * sd::s_minus_atan(s));
  };
  return T(2) * inv_t2 * sd::integrate_log_panels<T>(g, i_lo * sd::kPanelWidth, i_hi * sd::kPanelWidth);
}

}  // namespace brdfkit
