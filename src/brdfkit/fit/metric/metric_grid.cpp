#include "brdfkit/fit/metric/metric_grid.h"

#include <cmath>

#include "brdfkit/core/thread_scratch.h"

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

void build_chunk(const GridSpec& grid, size_t i, const MeasuredBrdf& data, MetricChunk& ch) {
  ch.clear();
  const AxisNode ti = grid.theta_i[i];
  const Vec3d wi(std::sin(ti.angle), 0.0, std::cos(ti.angle));
  const size_t n = grid.theta_o.size() * grid.phi.size();
  // The nodes with a weight and both directions above the horizon, in (θo, φ) order.
  struct RowBuffers {
    std::vector<Vec3d> wo;
    std::vector<double> weight, cos_phi, sin_phi;
    std::vector<std::optional<Rgb>> m;
  };
  ScratchLease<RowBuffers> lease;
  RowBuffers& buf = *lease;
  std::vector<Vec3d>& wo = buf.wo;
  std::vector<double> &weight = buf.weight, &cos_phi = buf.cos_phi, &sin_phi = buf.sin_phi;
  std::vector<std::optional<Rgb>>& m = buf.m;
  wo.clear();
  weight.clear();
  cos_phi.clear();
  sin_phi.clear();
  wo.reserve(n);
  weight.reserve(n);
  // cos φ, sin φ: the same for every θo row
  for (const AxisNode& ph : grid.phi) {
    cos_phi.push_back(std::cos(ph.angle));
    sin_phi.push_back(std::sin(ph.angle));
  }
  for (const AxisNode& to : grid.theta_o) {
    const double st = std::sin(to.angle), ct = std::cos(to.angle);
    for (size_t p = 0; p < grid.phi.size(); ++p) {
      const AxisNode& ph = grid.phi[p];
      const double w = ti.weight * to.weight * ph.weight;
      if (!(w > 0)) continue;
      const Vec3d o(st * cos_phi[p], st * sin_phi[p], ct);
      if (!(wi.z() > 0 && o.z() > 0)) continue;
      wo.push_back(o);
      weight.push_back(w);
    }
  }
  data.eval_row(wi, wo, m);
  for (auto* v : {&ch.wi_x, &ch.wi_y, &ch.wi_z, &ch.wo_x, &ch.wo_y, &ch.wo_z, &ch.sqrt_weight, &ch.factor})
    v->reserve(wo.size());
  for (auto& c : ch.measured) c.reserve(wo.size());
  const double factor = grid.cos_i_factor ? wi.z() : 1.0;
  for (size_t k = 0; k < wo.size(); ++k) {
    if (!m[k] || !m[k]->allFinite()) continue;
    ch.push(wi, wo[k], weight[k], factor, *m[k]);
  }
}

MetricChunk build_chunk(const GridSpec& grid, size_t i, const MeasuredBrdf& data) {
  MetricChunk ch;
  build_chunk(grid, i, data, ch);
  return ch;
}

}  // namespace brdfkit::fit
