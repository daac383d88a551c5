// Holzschuch & Pacanowski 2015 (seed 004) Eq. 31: RMSE = [∫ (ρM − ρE)² cos²θi dωo dθi]^½,
// θi every 1°, θo and φo every 0.25°, θ < 1.4 rad (§6.3), φo over the full circle (DESIGN.md §7).
// The channels are averaged. 37 million samples: the domain is rebuilt per evaluation rather
// than kept.
// On scattered samples (metric_samples.h) and a MERL table's cells (metric_cells.h) the same
// integral: dθi dωo = dωi dωo / (2π sinθi) (isotropy: the φi integral is 2π), so
// μ = 1/(2π sinθi), θi, θo < 1.4 rad. On cells that is 1.5 M samples instead of the grid's 37 M
// nearest-cell look-ups, and the model is compared where each value was measured.
#include "brdfkit/fit/metric/metric_definition.h"

namespace brdfkit::fit {

namespace {
double hp_density(const Vec3d& wi, const Vec3d& wo) {
  const double c14 = std::cos(1.4);  // θ < 1.4 rad, strictly
  if (!(wi.z() > c14 && wo.z() > c14)) return 0.0;
  const double sin_i = std::sqrt(wi.x() * wi.x() + wi.y() * wi.y());
  return sin_i > 0 ? 1.0 / (2 * kPi * sin_i) : 0.0;
}
}  // namespace

MetricDefinition hp_rmse_metric(int coarsen) {
  const double deg = kPi / 180.0;
  const double limit = 1.4 - 1e-12;  // θ < 1.4 rad, strictly
  MetricDefinition d;
  d.grid.theta_i = regular_nodes(0.0, limit, deg * coarsen);
  d.grid.theta_o = regular_nodes(0.0, limit, 0.25 * deg * coarsen);
  d.grid.phi = regular_nodes(0.0, (360 - 0.25 * coarsen) * deg, 0.25 * deg * coarsen);
  for (AxisNode& n : d.grid.theta_o) n.weight *= std::sin(n.angle);
  d.grid.cos_i_factor = true;
  d.channel_pool = 1.0 / 3.0;
  d.cache = false;
  d.cells = {&hp_density, true, true};
  return d;
}

}  // namespace brdfkit::fit
