// Löw et al. 2012 (seed 003) Eq. 29–33: g = cosθi ρ (E1) or ln(1 + cosθi ρ) (E2),
// E = Σ_k,l (g − ĝ)² sinθo Δφo Δθo Δθi, θi every 10°, θo and φo every 1° (§5.1: "360 × 80
// samples per θi"), θ ≤ 80° inclusive (DESIGN.md §7), the channels' errors summed (§5.1).
//
// Eq. 33 is first an integral, ∫∫∫ (g − ĝ)² sinθo dφo dθo dθi, which the sum samples with θi every
// 10° because "the shape of the gloss changes slowly" (§5.1). On a MERL table the integral runs
// over the table's cells instead (metric_cells.h): dθi dωo = dωi dωo / (2π sinθi) (isotropy: the
// φi integral is 2π), so μ = 1/(2π sinθi) at the cell centre, θi, θo ≤ 80°. The value approximates
// the same integral as the paper's sum. E2's logarithm is not linear in ρ, so its cells are not
// folded: each orientation is its own sample. On scattered samples (metric_samples.h) the same μ
// times each sample's pair measure (a θi = 0 sample would get μ = 0; the Cornell files have none).
#include "brdfkit/fit/metric/metric_definition.h"

namespace brdfkit::fit {

namespace {
double low_density(const Vec3d& wi, const Vec3d& wo) {
  const double c80 = std::cos(80 * kPi / 180) - 1e-12;  // θ ≤ 80° inclusive
  if (!(wi.z() >= c80 && wo.z() >= c80)) return 0.0;
  const double sin_i = std::sqrt(wi.x() * wi.x() + wi.y() * wi.y());
  return sin_i > 0 ? 1.0 / (2 * kPi * sin_i) : 0.0;
}
}  // namespace

MetricDefinition low_metric(int m, int coarsen) {
  const double deg = kPi / 180.0;
  MetricDefinition d;
  d.grid.theta_i = regular_nodes(0.0, 80 * deg, 10 * deg * coarsen);
  d.grid.theta_o = regular_nodes(0.0, 80 * deg, deg * coarsen);
  d.grid.phi = regular_nodes(0.0, (360 - coarsen) * deg, deg * coarsen);
  for (AxisNode& n : d.grid.theta_o) n.weight *= std::sin(n.angle);
  d.grid.cos_i_factor = true;
  d.transform = m == 2 ? Transform::Log1p : Transform::Identity;
  d.sqrt = false;
  d.channel_pool = 1.0;
  d.cells = {&low_density, true, m != 2};
  return d;
}

}  // namespace brdfkit::fit
