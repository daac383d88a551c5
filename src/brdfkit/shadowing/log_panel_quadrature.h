#pragma once
// The quadrature of the Smith Λ integral (shadowing/smith_integral.h) in w = log s: a composite
// Gauss-Legendre rule (Boost's nodes) on panels of width kPanelWidth, laid downwards from the
// upper end of the window, after a scan of the integrand at the panels' edges that skips the
// panels where it is negligible and splits the steep ones. The rule is fixed once the pieces are
// chosen, so Jets differentiate the quadrature sum exactly.
#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

namespace brdfkit::smith_detail {

// Scalar part of a double or a ceres::Jet (which has a member `a`).
template <class T> double scalar(const T& x) {
  if constexpr (std::is_arithmetic_v<T>)
    return static_cast<double>(x);
  else
    return x.a;
}

inline constexpr double kPanelWidth = 0.5;  // in w = log s
inline constexpr int kGaussPoints = 7;  // odd: the rule's middle point is at abscissa 0
using GaussRule = boost::math::quadrature::gauss<double, kGaussPoints>;

// A piece of a panel, integrated by the Gauss-Legendre rule: its middle and half width in w, the
// panel it lies in (counted from the lowest) and whether it is that whole panel.
struct Piece {
  double mid, half;
  int panel;
  bool whole;
};

// The pieces to integrate (into `pieces`), from |g| at the edges of the panels laid from `hi`
// downwards (edge j + 1 − n_panels at hi − j·kPanelWidth), skipping panels where g is negligible.
// Non-finite edge values count as 0.
inline void active_pieces(std::vector<double>& edge, double hi, std::vector<Piece>& pieces) {
  pieces.clear();
  const int n_panels = static_cast<int>(edge.size()) - 1;
  auto panel_lo = [&](int j) { return hi - (n_panels - j) * kPanelWidth; };
  double gmax = 0.0;
  for (double& e : edge) {
    if (!std::isfinite(e)) e = 0.0;
    gmax = std::max(gmax, e);
  }
  if (!(gmax > 0.0)) return;
  // Floored at the smallest normal double: 1e-14·gmax underflows to 0 for gmax below ~2e-294.
  // Below that floor g is negligible.
  const double cut = std::max(1e-14 * gmax, std::numeric_limits<double>::min());
  auto active = [&](int j) { return j >= 0 && j < n_panels && (edge[j] > cut || edge[j + 1] > cut); };
  constexpr double kE4 = 54.598150033144236;  // e⁴
  for (int j = 0; j < n_panels; ++j) {
    // A panel next to an active one is integrated too: a feature narrower than the scan step
    // between two negligible edge values would otherwise be lost.
    if (!(active(j) || active(j - 1) || active(j + 1))) continue;
    // Steep panels (sharp cut-offs such as exp(−x^p) with large p, a step of width ~1/(2p) in w)
    // are split so that each piece spans at most a factor e⁴ of the integrand (its edge values
    // floored at the cut): n pieces, the least n ≤ 32 with high ≤ low·e⁴ⁿ.
    const double a = std::max(edge[j], cut), b = std::max(edge[j + 1], cut);
    const double high = std::max(a, b);
    double bound = std::min(a, b) * kE4;
    int n = 1;
    for (; n < 32 && high > bound; ++n) bound *= kE4;
    const double width = n == 1 ? kPanelWidth : kPanelWidth / n, half = 0.5 * width;
    for (int piece = 0; piece < n; ++piece) pieces.push_back({panel_lo(j) + (piece + 0.5) * width, half, j, n == 1});
  }
}

// The rule's points of a piece in the order rule_sum reads them: the middle one (abscissa 0) once,
// the others as ± pairs.
inline double* rule_points(const Piece& p, double* point) {
  for (const double x : GaussRule::abscissa()) {
    if (x == 0.0) {
      *point++ = p.mid;
    } else {
      *point++ = p.mid + p.half * x;
      *point++ = p.mid - p.half * x;
    }
  }
  return point;
}

// Σ over the pieces of the rule's weights times g at their points (value: rule_points' order).
template <class T> T rule_sum(const std::vector<Piece>& pieces, const std::vector<T>& value) {
  const auto& xs = GaussRule::abscissa();
  const auto& ws = GaussRule::weights();
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
  std::vector<Piece> pieces;
  active_pieces(edge, hi, pieces);
  at.resize(pieces.size() * kGaussPoints);
  double* point = at.data();
  for (const Piece& p : pieces) point = rule_points(p, point);
  g(at, value);
  return rule_sum(pieces, value);
}

// The same with g called point by point.
template <class T, class G> T integrate_log_panels(const G& g, double lo, double hi) {
  auto batch = [&](const std::vector<double>& w, std::vector<T>& out) {
    out.resize(w.size());
    for (size_t k = 0; k < w.size(); ++k) out[k] = g(w[k]);
  };
  return integrate_log_panels_batched<T>(batch, lo, hi);
}

}  // namespace brdfkit::smith_detail
