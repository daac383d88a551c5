#include "brdfkit/shadowing/smith_lattice_panels.h"

namespace brdfkit::smith_detail {

const LatticeFactors& LatticeFactors::get() {
  static const LatticeFactors lattice;
  return lattice;
}

// The points as integrate_lattice_panels lays them (a whole panel is the piece with its middle at
// its lower edge + kPanelWidth/2), their factors from the same kernel at 1/tan²θ = 1, so that
// (1 + s²) · 1 is 1 + s² exactly.
LatticeFactors::LatticeFactors() {
  std::vector<double> edges, points;
  for (int i = kLo; i <= kHi; ++i) edges.push_back(i * kPanelWidth);
  points.resize(std::size_t(kHi - kLo) * kGaussPoints);
  double* point = points.data();
  for (int i = kLo; i < kHi; ++i) point = rule_points({i * kPanelWidth + 0.5 * kPanelWidth, 0.5 * kPanelWidth, 0, true}, point);
  edge_x_.resize(edges.size());
  edge_factor_.resize(edges.size());
  integrand_factors(1.0, edges.data(), edges.size(), edge_x_.data(), edge_factor_.data());
  point_x_.resize(points.size());
  point_factor_.resize(points.size());
  integrand_factors(1.0, points.data(), points.size(), point_x_.data(), point_factor_.data());
}

}  // namespace brdfkit::smith_detail
