// Löw et al. 2012 (seed 003) Eq. 29–33: g = cosθi ρ (E1) or ln(1 + cosθi ρ) (E2),
// E = Σ_k,l (g − ĝ)² sinθo Δφo Δθo Δθi, θi every 10°, θo and φo every 1° (§5.1: "360 × 80
// samples per θi"), θ ≤ 80° inclusive (DESIGN.md §7), the channels' errors summed (§5.1).
#include "brdfkit/fit/metric_definition.h"

namespace brdfkit::fit {

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
  return d;
}

}  // namespace brdfkit::fit
