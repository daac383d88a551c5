// Bagher et al. 2012 (seed 000) §6.3: E = (∫∫ (m − ρ)² cosθi cosθo dωi dωo)^½ over the full
// hemispheres minus the cells that were not measured (DESIGN.md §7). Midpoint rule on 1° cells
// in θi, θo ∈ [0°, 90°] and Δφ ∈ [0°, 180°]; dωi dωo = sinθi sinθo dθi dθo dφi dΔφ, where
// ∫ dφi = 2π (isotropy) and the Δφ ∈ [180°, 360°) half mirrors [0°, 180°) (factor 2). Channels
// averaged; reported over the max albedo like `ngan` (DESIGN.md §7).
// On a MERL table the integral runs over the table's cells (metric_cells.h): μ = cosθi cosθo at
// the cell centre times the cell's pair measure; on scattered samples (metric_samples.h) μ at the
// sample times its pair measure.
#include "brdfkit/fit/metric/metric_definition.h"

namespace brdfkit::fit {

namespace {
double bagher_density(const Vec3d& wi, const Vec3d& wo) { return wi.z() * wo.z(); }
}  // namespace

MetricDefinition bagher_metric(int coarsen) {
  const double deg = kPi / 180.0;
  MetricDefinition d;
  const int n_theta = 90 / coarsen, n_phi = 180 / coarsen;
  d.grid.theta_i = cell_centres(0.0, kPi / 2, n_theta);
  d.grid.theta_o = cell_centres(0.0, kPi / 2, n_theta);
  d.grid.phi = cell_centres(0.0, n_phi * coarsen * deg, n_phi, 2.0);
  for (AxisNode& n : d.grid.theta_i) n.weight *= 2 * kPi * std::sin(n.angle) * std::cos(n.angle);
  for (AxisNode& n : d.grid.theta_o) n.weight *= std::sin(n.angle) * std::cos(n.angle);
  d.grid.cos_i_factor = false;
  d.channel_pool = 1.0 / 3.0;
  d.divide_by_max_albedo = true;
  d.cells = {&bagher_density, false, true};
  return d;
}

}  // namespace brdfkit::fit
