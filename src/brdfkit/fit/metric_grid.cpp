#include "brdfkit/fit/metric_grid.h"

#include <cmath>

namespace brdfkit::fit {

std::vector<AxisNode> cell_centres(double lo, double hi, int n, double scale) {
  std::vector<AxisNode> nodes;
  nodes.reserve(size_t(n));
  const double width = (hi - lo) / n;
  for (int k = 0; k < n; ++k) nodes.push_back({lo + (k + 0.5) * width, scale * width});
  return nodes;
}

std::vector<AxisNode> regular_nodes(double lo, double hi, double step) {
  std::vector<AxisNode> nodes;
  const int n = int(std::floor((hi - lo) / step + 1e-9));
  for (int k = 0; k <= n; ++k) nodes.push_back({lo + k * step, step});
  return nodes;
}

MetricChunk build_chunk(const GridSpec& grid, size_t i, const MeasuredBrdf& data) {
  MetricChunk ch;
  const AxisNode ti = grid.theta_i[i];
  const Vec3d wi(std::sin(ti.angle), 0.0, std::cos(ti.angle));
  const size_t n = grid.theta_o.size() * grid.phi.size();
  for (auto* v : {&ch.wi_x, &ch.wi_y, &ch.wi_z, &ch.wo_x, &ch.wo_y, &ch.wo_z, &ch.sqrt_weight, &ch.factor})
    v->reserve(n);
  for (auto& m : ch.measured) m.reserve(n);
  const double factor = grid.cos_i_factor ? wi.z() : 1.0;
  for (const AxisNode& to : grid.theta_o) {
    const double st = std::sin(to.angle), ct = std::cos(to.angle);
    for (const AxisNode& ph : grid.phi) {
      const double w = ti.weight * to.weight * ph.weight;
      if (!(w > 0)) continue;
      const Vec3d wo(st * std::cos(ph.angle), st * std::sin(ph.angle), ct);
      if (!(wi.z() > 0 && wo.z() > 0)) continue;
      const std::optional<Rgb> m = data.eval(wi, wo);
      if (!m || !m->allFinite()) continue;
      ch.wi_x.push_back(wi.x());
      ch.wi_y.push_back(wi.y());
      ch.wi_z.push_back(wi.z());
      ch.wo_x.push_back(wo.x());
      ch.wo_y.push_back(wo.y());
      ch.wo_z.push_back(wo.z());
      ch.sqrt_weight.push_back(std::sqrt(w));
      ch.factor.push_back(factor);
      for (int c = 0; c < 3; ++c) ch.measured[size_t(c)].push_back((*m)[c]);
    }
  }
  return ch;
}

}  // namespace brdfkit::fit
