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
// smith_table.h). A scalar scan over a wide w range finds where the integrand lives; panels where
// it is negligible are skipped. The rule is fixed once the panels are
// chosen, so Jets differentiate the quadrature sum exactly.
//
// Compact support (Schlick's rational distribution vanishes beyond tan²θ = x_max, and x_max moves
// with its parameter): the integrand stops at s_max = sqrt(t² x_max − 1), with a kink there. Fixed
// panels in w would put that kink inside a panel whose rule does not see the edge move, so the Jet
// derivative missed the edge's motion (1e-4 relative in ∂/∂m). Instead the integral is
// reparametrized to a fixed domain, s = s_max e^u with u ≤ 0: the panels end exactly at the edge
// for every parameter value, and Jets differentiate through s_max (the Leibniz boundary term is
// carried by the substitution; it is zero here anyway since P22 → 0 at the edge).
// A distribution opts in by providing `T tan2_max() const` (x_max, +∞ when unbounded).
#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "brdfkit/shadowing/smith_integrand_block.h"

namespace brdfkit {

namespace smith_detail {

// Scalar part of a double or a ceres::Jet (which has a member `a`).
template <class T> double scalar(const T& x) {
  if constexpr (std::is_arithmetic_v<T>)
    return static_cast<double>(x);
  else
    return x.a;
}

// s − atan s without cancellation for small s (Taylor series, error < s¹¹/11), for doubles and Jets.
template <class T> T s_minus_atan(const T& s) {
  using std::atan;
  if (scalar(s) < 1e-2) {
    const T s2 = s * s;
    return s * s2 * (T(1.0 / 3) - s2 * (T(1.0 / 5) - s2 * (T(1.0 / 7) - s2 / T(9))));
  }
  return s - atan(s);
}

inline constexpr double kPanelWidth = 0.5;  // in w = log s
inline constexpr int kGaussPoints = 7;  // odd: the rule's middle point is at abscissa 0

// A piece of a panel, integrated by the Gauss-Legendre rule: its middle and half width in w.
struct Piece {
  double mid, half;
};

// The pieces to integrate, from |g| at the edges of the panels laid from `hi` downwards (edge
// j + 1 − n_panels at hi − j·kPanelWidth), skipping panels where g is negligible. Non-finite edge
// values count as 0.
inline std::vector<Piece> active_pieces(std::vector<double>& edge, double hi) {
  const int n_panels = static_cast<int>(edge.size()) - 1;
  auto panel_lo = [&](int j) { return hi - (n_panels - j) * kPanelWidth; };
  double gmax = 0.0;
  for (double& e : edge) {
    if (!std::isfinite(e)) e = 0.0;
    gmax = std::max(gmax, e);
  }
  if (!(gmax > 0.0)) return {};
  // Floored at the smallest normal double: 1e-14·gmax underflows to 0 for gmax below ~2e-294, and
  // log_edge would then subtract −∞ from −∞ (a NaN cast to int). Below that floor g is negligible.
  const double cut = std::max(1e-14 * gmax, std::numeric_limits<double>::min());
  auto active = [&](int j) { return j >= 0 && j < n_panels && (edge[j] > cut || edge[j + 1] > cut); };
  // log of an edge value, floored at the cut, to measure how steep a panel is; a panel's upper
  // edge is the next one's lower edge, so each log is taken once.
  auto log_edge = [&](int j) { return std::log(std::max(edge[j], cut)); };
  int logged = -1;  // the edge whose log is in log_lo
  double log_lo = 0;
  std::vector<Piece> pieces;
  pieces.reserve(size_t(n_panels));
  for (int j = 0; j < n_panels; ++j) {
    // A panel next to an active one is integrated too: a feature narrower than the scan step
    // between two negligible edge values would otherwise be lost.
    if (!(active(j) || active(j - 1) || active(j + 1))) continue;
    // Steep panels (sharp cut-offs such as exp(−x^p) with large p, a step of width ~1/(2p) in w)
    // are split so that each piece spans at most a factor e⁴ of the integrand.
    const double log_j = logged == j ? log_lo : log_edge(j);
    log_lo = log_edge(j + 1);
    logged = j + 1;
    const int n = std::clamp(static_cast<int>(std::ceil(std::abs(log_lo - log_j) / 4.0)), 1, 32);
    const double width = kPanelWidth / n, half = 0.5 * width;
    for (int piece = 0; piece < n; ++piece) pieces.push_back({panel_lo(j) + (piece + 0.5) * width, half});
  }
  return pieces;
}

// ∫ g over [lo, hi] by Gauss-Legendre on panels of width kPanelWidth laid from `hi` downwards
// (so a finite edge at `hi` is a panel edge), skipping panels where g is negligible.
// g is called on batches: g(w, out) sets out[k] = g(w[k]) for every point of w (out resized), so
// that a distribution with a vector P22 evaluates the scan and then the rule's points together.
template <class T, class GBatch> T integrate_log_panels_batched(const GBatch& g, double lo, double hi) {
  const int n_panels = static_cast<int>(std::ceil((hi - lo) / kPanelWidth));
  std::vector<double> at(size_t(n_panels) + 1);
  for (int j = 0; j <= n_panels; ++j) at[size_t(j)] = hi - (n_panels - j) * kPanelWidth;
  std::vector<T> value;
  g(at, value);
  std::vector<double> edge(at.size());
  for (size_t j = 0; j < at.size(); ++j) edge[j] = std::abs(scalar(value[j]));
  const std::vector<Piece> pieces = active_pieces(edge, hi);
  using Rule = boost::math::quadrature::gauss<double, kGaussPoints>;
  const auto& xs = Rule::abscissa();
  const auto& ws = Rule::weights();
  // The rule's points, piece by piece: the middle one (abscissa 0) once, the others as ± pairs.
  at.resize(pieces.size() * kGaussPoints);
  double* point = at.data();
  for (const Piece& p : pieces)
    for (size_t i = 0; i < xs.size(); ++i) {
      if (xs[i] == 0.0) {
        *point++ = p.mid;
      } else {
        *point++ = p.mid + p.half * xs[i];
        *point++ = p.mid - p.half * xs[i];
      }
    }
  g(at, value);
  T sum(0);
  size_t k = 0;
  for (const Piece& p : pieces)
    for (size_t i = 0; i < xs.size(); ++i) {
      if (xs[i] == 0.0) {
        sum += value[k++] * T(ws[i] * p.half);
      } else {
        sum += (value[k] + value[k + 1]) * T(ws[i] * p.half);
        k += 2;
      }
    }
  return sum;
}

// The same with g called point by point.
template <class T, class G> T integrate_log_panels(const G& g, double lo, double hi) {
  auto batch = [&](const std::vector<double>& w, std::vector<T>& out) {
    out.resize(w.size());
    for (size_t k = 0; k < w.size(); ++k) out[k] = g(w[k]);
  };
  return integrate_log_panels_batched<T>(batch, lo, hi);
}

}  // namespace smith_detail

// Λ(tanθ) from ndf.P22 (any type with `U P22(const U& x) const`, U = T).
template <class Ndf, class T> T smith_lambda_integral(const Ndf& ndf, const T& tan_theta) {
  namespace sd = smith_detail;
  const double t0 = sd::scalar(tan_theta);
  if (!(t0 > 0.0)) return T(0);
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
  // Integrand in w = log s, including the Jacobian ds = s dw.
  if constexpr (std::is_same_v<T, double> && sd::HasP22Block<Ndf>) {
    auto g = [&](const std::vector<double>& w, std::vector<double>& out) { sd::integrand_batch(ndf, inv_t2, w, out); };
    return 2.0 * inv_t2 * sd::integrate_log_panels_batched<double>(g, w_lo, w_hi);
  }
  auto g = [&](double w) -> T {
    const double s = std::exp(w);
    const T x = (T(1) + T(s * s)) * inv_t2;
    return ndf.P22(x) * T(s * s * sd::s_minus_atan(s));
  };
  return T(2) * inv_t2 * sd::integrate_log_panels<T>(g, w_lo, w_hi);
}

}  // namespace brdfkit
