#pragma once
// The Smith Λ integral (shadowing/smith_integral.h) for distributions with a vector P22, its
// integrand's other factors (x = (1 + s²)/t² and s²(s − atan s), smith_integrand_block.h) read from
// a lattice. smith_lambda_integral lays its panels on w = i·kPanelWidth whatever tanθ is, so the
// edges and the rule's points of every whole panel are the same in every integral of a process:
// their s², exp and atan are computed once (LatticeFactors), and an integral pays for P22 at its
// points, a product and the sum. (A Smith table node is 161 such integrals; a Cornell file's GTR
// fit, krylon_blue, took 0.77 s of CPU before, 0.51–0.57 s with this, active_pieces' split without
// logs and the per-thread scratch.) The values are those of the integrand computed afresh, to the bit.
#include <cstddef>
#include <vector>

#include "brdfkit/shadowing/log_panel_quadrature.h"
#include "brdfkit/shadowing/smith_integrand_block.h"

namespace brdfkit::smith_detail {

// 1 + s² and s²(s − atan s) (integrand_factors at 1/tan²θ = 1) at the lattice's edges and at the
// rule's points of its whole panels, built on first use (a function-local static: thread-safe).
class LatticeFactors {
 public:
  // Panels [i, i + 1)·kPanelWidth for kLo ≤ i < kHi: w ∈ [−100, 100], the window of every tanθ
  // from e^−70 to e^55 (smith_lambda_integral's window is [−30 + min(0, ln t), 45 + max(0, ln t)]).
  static constexpr int kLo = -200, kHi = 200;
  static const LatticeFactors& get();

  bool covers(int i_lo, int i_hi) const { return i_lo >= kLo && i_hi <= kHi; }
  // At the edge w = i·kPanelWidth, kLo ≤ i ≤ kHi.
  double edge_x(int i) const { return edge_x_[std::size_t(i - kLo)]; }
  double edge_factor(int i) const { return edge_factor_[std::size_t(i - kLo)]; }
  // At the kGaussPoints points of panel i, in rule_points' order.
  const double* point_x(int i) const { return point_x_.data() + std::size_t(i - kLo) * kGaussPoints; }
  const double* point_factor(int i) const { return point_factor_.data() + std::size_t(i - kLo) * kGaussPoints; }

 private:
  LatticeFactors();  // smith_lattice_panels.cpp
  std::vector<double> edge_x_, edge_factor_, point_x_, point_factor_;
};

// out[k] = P22(x[k]) · factor[k] for every k, P22 on vector lanes kP22Block at a time.
template <HasP22Block Ndf>
void p22_products(const Ndf& ndf, const std::vector<double>& x, const std::vector<double>& factor,
                  std::vector<double>& out) {
  out.resize(x.size());
  double xb[kP22Block], p22[kP22Block];
  for (std::size_t b = 0; b < x.size(); b += kP22Block) {
    const std::size_t n = std::min(kP22Block, x.size() - b);
    std::fill(std::copy_n(x.data() + b, n, xb), xb + kP22Block, 1.0);  // padding: any slope
    ndf.P22_block(xb, p22);
    for (std::size_t k = 0; k < n; ++k) out[b + k] = p22[k] * factor[b + k];
  }
}

// What an integral needs beside its result, kept per thread so that the integrals of a table
// node do not allocate.
struct LatticeScratch {
  std::vector<double> w, x, factor, value, edge, at, fresh_x, fresh_factor;
  std::vector<std::size_t> fresh;
  std::vector<Piece> pieces;
};

// The factors at the points w[k], k ∈ s.fresh, afresh: the points of split pieces, or of a window
// beyond the lattice.
inline void fresh_factors(double inv_t2, LatticeScratch& s) {
  const std::size_t n = s.fresh.size();
  s.at.resize(n);
  s.fresh_x.resize(n);
  s.fresh_factor.resize(n);
  for (std::size_t k = 0; k < n; ++k) s.at[k] = s.w[s.fresh[k]];
  integrand_factors(inv_t2, s.at.data(), n, s.fresh_x.data(), s.fresh_factor.data());
  for (std::size_t k = 0; k < n; ++k) {
    s.x[s.fresh[k]] = s.fresh_x[k];
    s.factor[s.fresh[k]] = s.fresh_factor[k];
  }
}

// ∫ P22((1 + s²)/t²) s²(s − atan s) dw over the panels i_lo ≤ i < i_hi (inv_t2 = 1/t²):
// integrate_log_panels_batched's pieces, points and sum.
template <HasP22Block Ndf> double integrate_lattice_panels(const Ndf& ndf, double inv_t2, int i_lo, int i_hi) {
  const LatticeFactors& lattice = LatticeFactors::get();
  const bool on_lattice = lattice.covers(i_lo, i_hi);
  thread_local LatticeScratch s;
  const std::size_t n_edges = std::size_t(i_hi - i_lo) + 1;
  s.w.resize(n_edges);
  s.x.resize(n_edges);
  s.factor.resize(n_edges);
  s.fresh.clear();
  for (std::size_t j = 0; j < n_edges; ++j) {
    const int i = i_lo + int(j);
    s.w[j] = i * kPanelWidth;
    if (on_lattice) {
      s.x[j] = lattice.edge_x(i) * inv_t2;  // the kernel's (1 + s²) · inv_t2
      s.factor[j] = lattice.edge_factor(i);
    } else {
      s.fresh.push_back(j);
    }
  }
  fresh_factors(inv_t2, s);
  p22_products(ndf, s.x, s.factor, s.value);
  s.edge.resize(n_edges);
  for (std::size_t j = 0; j < n_edges; ++j) s.edge[j] = std::abs(s.value[j]);
  active_pieces(s.edge, i_hi * kPanelWidth, s.pieces);

  const std::size_t n_points = s.pieces.size() * kGaussPoints;
  s.w.resize(n_points);
  s.x.resize(n_points);
  s.factor.resize(n_points);
  s.fresh.clear();
  double* point = s.w.data();
  for (const Piece& p : s.pieces) {
    const std::size_t first = std::size_t(point - s.w.data());
    point = rule_points(p, point);
    if (on_lattice && p.whole) {
      const double *x = lattice.point_x(i_lo + p.panel), *factor = lattice.point_factor(i_lo + p.panel);
      for (std::size_t k = 0; k < kGaussPoints; ++k) {
        s.x[first + k] = x[k] * inv_t2;
        s.factor[first + k] = factor[k];
      }
    } else {
      for (std::size_t k = 0; k < kGaussPoints; ++k) s.fresh.push_back(first + k);
    }
  }
  fresh_factors(inv_t2, s);
  p22_products(ndf, s.x, s.factor, s.value);
  return rule_sum(s.pieces, s.value);
}

}  // namespace brdfkit::smith_detail
