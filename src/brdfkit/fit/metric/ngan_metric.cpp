// Ngan et al. 2005 (seed 002) Eq. 1: E = sqrt(Σ w (R cosθi − M cosθi)² / Σ w), θi, θo ≤ 80°,
// w the solid-angle weight, reported over the max albedo (§4.1). Grid of DESIGN.md §7: 1° cells
// with centres θ = 0.5°…79.5°, Δφ = 0.5°…179.5° (isotropy: the other half of Δφ mirrors this
// one and would only double both sums), w = sinθi sinθo, the three channels pooled in one sum
// (so the denominator counts each sample once per channel).
//
// On a MERL table the bins are the table's own cells (metric_cells.h): Eq. 1 sums over "the
// non-empty bins of R" with w "the solid angle correction term", which for a cell is its pair
// measure ∫ dωi dωo; a cell is in the domain when θi, θo ≤ 80° at its centre.
// On scattered samples (metric_samples.h) w is a sample's pair measure (reader's dωo × its θi
// ring's band of dωi), same density and cut-off, the cosθi of the sample's own wi.
#include "brdfkit/fit/metric/metric_definition.h"

namespace brdfkit::fit {

namespace {
double ngan_density(const Vec3d& wi, const Vec3d& wo) {
  const double c80 = std::cos(80 * kPi / 180) - 1e-12;  // θ ≤ 80° inclusive
  return wi.z() >= c80 && wo.z() >= c80 ? 1.0 : 0.0;
}
}  // namespace

MetricDefinition ngan_metric(int coarsen) {
  const double deg = kPi / 180.0;
  MetricDefinition d;
  const int n_theta = 80 / coarsen, n_phi = 180 / coarsen;
  d.grid.theta_i = cell_centres(0.0, n_theta * coarsen * deg, n_theta);
  d.grid.theta_o = cell_centres(0.0, n_theta * coarsen * deg, n_theta);
  d.grid.phi = cell_centres(0.0, n_phi * coarsen * deg, n_phi);
  // w = sinθi sinθo: the cell widths are equal and cancel against Σ w.
  for (auto* axis : {&d.grid.theta_i, &d.grid.theta_o})
    for (AxisNode& n : *axis) n.weight = std::sin(n.angle);
  for (AxisNode& n : d.grid.phi) n.weight = 1.0;
  d.grid.cos_i_factor = true;
  d.channel_pool = 1.0 / 3.0;
  d.divide_by_weight_sum = true;
  d.divide_by_max_albedo = true;
  d.cells = {&ngan_density, true, true};
  return d;
}

}  // namespace brdfkit::fit
