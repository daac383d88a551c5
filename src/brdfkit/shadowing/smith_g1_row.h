#pragma once
// Smith G1 of one distribution at fixed parameters as a 1-D table over the direction, for the batch
// loops that evaluate a model at thousands of direction pairs with the same parameters: the
// Λ table of smith_table.h costs a 4^d-node stencil, a log and an exp per direction; this row costs
// one division and a four-tap interpolation, with no transcendental function.
//
// Coordinate: w = r/(1 + r), r = (tanθ − t_e)/(t½ − t_e), where t_e is the support edge (Λ = 0 for
// tanθ ≤ t_e) and t½ the tangent where Λ = 1 (G1 = ½). w maps [t_e, ∞) onto [0, 1) with the
// lobe's transition at w = ½ whatever the width, and G1(w) is smooth on all of it: → 1 as w → 0
// (Λ vanishes like a power or faster), → 0 linearly as w → 1 (Λ grows like tanθ for a finite mean
// slope). Values: G1 at kNodes + 1 uniform nodes (G1 = 0 at w = 1), Catmull-Rom between them with
// quadratic ghosts at the ends (as smith_table.h). tests/shadowing/test_smith_g1_row.cpp measures
// the error against smith_g1 for every distribution with a numeric Λ: below 1e-6 (worst 4.7e-7,
// exponential-power; Beckmann 3.5e-9).
#include <algorithm>
#include <array>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <vector>

#include "brdfkit/shadowing/smith.h"

namespace brdfkit {

class SmithG1Row {
 public:
  static constexpr int kNodes = 1024;

  SmithG1Row() = default;
  // Tabulates G1 = 1/(1 + Λ) of `lambda`, a function of tanθ, with support edge t_edge.
  template <class Lambda> SmithG1Row(const Lambda& lambda, double t_edge) : t_edge_(t_edge) {
    scale_ = half_width(lambda);
    g_[0] = 0;  // ghost, set below
    for (int k = 0; k < kNodes; ++k) {
      const double w = double(k) / kNodes;
      const double t = t_edge_ + scale_ * w / (1 - w);
      g_[size_t(k) + 1] = 1 / (1 + lambda(t));
    }
    g_[kNodes + 1] = 0;  // w = 1: tanθ = ∞
    g_[0] = 3 * g_[1] - 3 * g_[2] + g_[3];
    g_[kNodes + 2] = 3 * g_[kNodes + 1] - 3 * g_[kNodes] + g_[kNodes - 1];
  }

  // G1 at cosθ (0 for cosθ ≤ 0, 1 at and inside the support edge). With s = sinθ, c = cosθ:
  // w = (t − t_e)/(t − t_e + t½ − t_e) = (s − t_e c)/(s + (t½ − 2 t_e) c), one division.
  double g1(double cos_theta) const {
    if (!(cos_theta > 0)) return 0;
    const double c = cos_theta, s = std::sqrt(std::max(0.0, 1 - c * c));
    const double num = s - t_edge_ * c;
    if (!(num > 0)) return 1;
    const double x = num / (num + scale_ * c) * kNodes;
    const int i = std::min(int(x), kNodes - 1);
    const double f = x - i, f2 = f * f, f3 = f2 * f;
    const double* g = g_.data() + i;  // nodes i − 1 … i + 2 are g[0] … g[3]
    return 0.5 * ((-f3 + 2 * f2 - f) * g[0] + (3 * f3 - 5 * f2 + 2) * g[1] + (-3 * f3 + 4 * f2 + f) * g[2] +
                  (f3 - f2) * g[3]);
  }

  // g1 at the kDBlock cosines of a batch block (ndf/d_block.h: callers pad it), the same values
  // to the bit (smith_g1_row_block.cpp): once per run of equal cosines where they repeat (through a
  // metric grid's chunk cosθi is constant and cosθo changes every 180 pairs), else with vector
  // instructions.
  void g1_block(const double* cos_theta, double* out) const;

 private:
  // g1 at every lane of a block as vector arithmetic.
  void g1_lanes(const double* cos_theta, double* out) const;
  // t½ − t_e, where Λ(t½) = 1 (monotone in tanθ: toms748 on log Λ over log r).
  template <class Lambda> double half_width(const Lambda& lambda) const {
    auto f = [&](double lr) {
      const double l = lambda(t_edge_ + std::exp(lr));
      return l > 0 ? std::log(l) : -745.0;
    };
    double lo = -1, hi = 1;
    while (f(lo) > 0 && lo > -60) lo -= 4;
    while (f(hi) < 0 && hi < 60) hi += 4;
    std::uintmax_t iterations = 100;
    const auto [a, b] = boost::math::tools::toms748_solve(f, lo, hi, boost::math::tools::eps_tolerance<double>(40),
                                                          iterations);
    return std::exp(0.5 * (a + b));
  }

  double t_edge_ = 0, scale_ = 1;
  std::array<double, kNodes + 3> g_{};  // g_[k + 1] = G1 at node k; ghosts at 0 and kNodes + 2
};

// The row of distribution `ndf` (one with a SmithShape: its coordinates key the row), from a per-thread cache
// of the last four parameter sets used: batch loops ask once per block of pairs, and a Jacobian's
// sweep asks, block after block, for the base point and for each shape variable's shifted point
// (three sets for a two-parameter distribution; with fewer entries than sets, every block would
// rebuild every row).
template <template <class> class Ndf> const SmithG1Row& smith_g1_row(const Ndf<double>& ndf) {
  using Shape = SmithShape<Ndf>;
  static_assert(Shape::kDims > 0, "smith_g1_row keys its cache by the SmithShape coordinates");
  struct Entry {
    std::array<double, Shape::kDims> key{};
    std::uint64_t used = 0;  // 0: empty
    SmithG1Row row;
  };
  thread_local std::array<Entry, 4> cache;
  thread_local std::uint64_t clock = 0;
  const std::array<double, Shape::kDims> key = Shape::values(ndf);
  for (Entry& e : cache)
    if (e.used && e.key == key) {
      e.used = ++clock;
      return e.row;
    }
  Entry& e = *std::min_element(cache.begin(), cache.end(), [](const Entry& a, const Entry& b) { return a.used < b.used; });
  double edge = 0;
  if constexpr (requires { Shape::tan_edge(key.data()); }) edge = Shape::tan_edge(key.data());
  e.row = SmithG1Row([&](double t) { return smith_lambda(ndf, t); }, edge);
  e.key = key;
  e.used = ++clock;
  return e.row;
}

}  // namespace brdfkit
