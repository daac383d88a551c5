#include "brdfkit/fit/metric_cells.h"

#include <tbb/parallel_for.h>

#include <cmath>

#include "brdfkit/core/half_diff.h"

namespace brdfkit::fit {

namespace {

constexpr int kThetaDBlock = 15;  // θd rows per chunk: 6 chunks per θh row

// Pair measure of the index block [h0, h1) × [d0, d1) × [p0, p1): the cell measure of
// measured/merl_brdf.h (merl_cell_weight) is a product of one factor per axis, so a block's is
// the product of the factors' sums: 2π (cos θh₀ − cos θh₁) · 2 (sin²θd₁ − sin²θd₀) · 2 Δφd.
double block_measure(int h0, int h1, int d0, int d1, int p0, int p1) {
  using namespace merl;
  auto theta_h = [](int i) {
    const double u = double(i) / kResThetaH;
    return u * u * (kPi / 2);
  };
  auto sin2_theta_d = [](int j) {
    const double s = std::sin(double(j) / kResThetaD * (kPi / 2));
    return s * s;
  };
  return 2 * kPi * (std::cos(theta_h(h0)) - std::cos(theta_h(h1))) * 2 * (sin2_theta_d(d1) - sin2_theta_d(d0)) * 2 *
         (kPi * (p1 - p0) / kResPhiD);
}

void push(MetricChunk& ch, const Vec3d& wi, const Vec3d& wo, double weight, double factor, const Rgb& m) {
  ch.wi_x.push_back(wi.x());
  ch.wi_y.push_back(wi.y());
  ch.wi_z.push_back(wi.z());
  ch.wo_x.push_back(wo.x());
  ch.wo_y.push_back(wo.y());
  ch.wo_z.push_back(wo.z());
  ch.sqrt_weight.push_back(std::sqrt(weight));
  ch.factor.push_back(factor);
  for (int c = 0; c < 3; ++c) ch.measured[size_t(c)].push_back(m[c]);
}

}  // namespace

CellDomain build_cell_domain(const merl::Table& table, const CellWeighting& weighting, int coarsen) {
  using namespace merl;
  const int k = coarsen;
  const int nh = kResThetaH / k, nd = kResThetaD / k, np = kResPhiD / k;
  const int blocks_d = (nd + kThetaDBlock - 1) / kThetaDBlock;
  std::vector<MetricChunk> chunks(size_t(nh * blocks_d));
  std::vector<double> measure(chunks.size(), 0.0);
  tbb::parallel_for(size_t(0), chunks.size(), [&](size_t i) {
    const int bh = int(i) / blocks_d, bd0 = int(i) % blocks_d * kThetaDBlock;
    MetricChunk& ch = chunks[i];
    double sum = 0;
    for (int bd = bd0; bd < std::min(nd, bd0 + kThetaDBlock); ++bd)
      for (int bp = 0; bp < np; ++bp) {
        const Cell c{bh * k + k / 2, bd * k + k / 2, bp * k + k / 2};
        const size_t off = cell_offset(c);
        if (!table.valid(off)) continue;
        Vec3d wi, wo;
        if (!cell_directions(c, wi, wo)) continue;
        const double mu_io = weighting.density(wi, wo), mu_oi = weighting.density(wo, wi);
        if (!(mu_io > 0 || mu_oi > 0)) continue;
        const double w = block_measure(bh * k, bh * k + k, bd * k, bd * k + k, bp * k, bp * k + k);
        sum += w;
        const Rgb m = table.value(off);
        const double fi = weighting.cos_i_factor ? wi.z() : 1.0, fo = weighting.cos_i_factor ? wo.z() : 1.0;
        if (weighting.fold) {
          push(ch, wi, wo, 0.5 * w * (mu_io * fi * fi + mu_oi * fo * fo), 1.0, m);
        } else {
          if (mu_io > 0) push(ch, wi, wo, 0.5 * w * mu_io, fi, m);
          if (mu_oi > 0) push(ch, wo, wi, 0.5 * w * mu_oi, fo, m);
        }
      }
    measure[i] = sum;
  });
  CellDomain d;
  d.chunks = std::move(chunks);
  for (double s : measure) d.measure_sum += s;  // chunk order: deterministic
  return d;
}

}  // namespace brdfkit::fit
