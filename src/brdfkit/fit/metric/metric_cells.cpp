#include "brdfkit/fit/metric/metric_cells.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "brdfkit/core/half_diff.h"

namespace brdfkit::fit {

namespace {

constexpr int kThetaDBlock = 15;  // θd rows per chunk: 6 chunks per θh row

int theta_d_blocks(int coarsen) { return (merl::kResThetaD / coarsen + kThetaDBlock - 1) / kThetaDBlock; }

// Pair measure of the index block [h0, h1) × [d0, d1) × [p0, p1): the cell measure of
// measured/merl_brdf.h (merl_cell_weight) is a product of one factor per axis, so a block's is
// the product of the factors' sums: 2π (cos θh₀ − cos θh₁) · 2 (sin²θd₁ − sin²θd₀) · 2 Δφd.
// The θh factor is one per chunk and the θd factor one per row, so they are computed there.
double theta_h_factor(int h0, int h1) {
  auto theta_h = [](int i) {
    const double u = double(i) / merl::kResThetaH;
    return u * u * (kPi / 2);
  };
  return std::cos(theta_h(h0)) - std::cos(theta_h(h1));
}
double theta_d_factor(int d0, int d1) {
  auto sin2_theta_d = [](int j) {
    const double s = std::sin(double(j) / merl::kResThetaD * (kPi / 2));
    return s * s;
  };
  return sin2_theta_d(d1) - sin2_theta_d(d0);
}
double phi_d_factor(int cells) { return kPi * cells / merl::kResPhiD; }  // Δφd of `cells` φd cells
double block_measure(double h, double d, double p) { return 2 * kPi * h * 2 * d * 2 * p; }

// merl::cell_directions of every cell, to the bit, with the sines and cosines computed once per
// θh row and per (θd, φd) instead of four times per cell: from_half_diff's arithmetic (core/
// half_diff.cpp) with the same factors. d = spherical_direction(θd, φd); wi = rotate_about(d, y, θh)
// written out for the y axis (axis·v = v_y, axis×v = (v_z, 0, −v_x), the zero terms dropped: adding
// ±0 changes no value); the rotation about z by φh that follows is the identity (merl::cell_centre
// puts every cell at φh = 0); wo = reflect(wi, h).
class CellDirections {
 public:
  CellDirections() : d_(size_t(merl::kResThetaD) * merl::kResPhiD) {
    for (int j = 0; j < merl::kResThetaD; ++j)
      for (int k = 0; k < merl::kResPhiD; ++k) {
        const HalfDiff hd = merl::cell_centre({0, j, k});
        d_[size_t(j) * merl::kResPhiD + size_t(k)] = spherical_direction(hd.theta_d, hd.phi_d);
      }
  }

  struct Row {
    Vec3d h;
    double cos_h, sin_h;
  };
  static Row row(int theta_h) {
    const HalfDiff hd = merl::cell_centre({theta_h, 0, 0});
    return {spherical_direction(hd.theta_h, hd.phi_h), std::cos(hd.theta_h), std::sin(hd.theta_h)};
  }

  // False when either direction is at or below the horizon (as merl::cell_directions).
  bool operator()(const Row& r, int theta_d, int phi_d, Vec3d& wi, Vec3d& wo) const {
    const Vec3d& d = d_[size_t(theta_d) * merl::kResPhiD + size_t(phi_d)];
    const double c = r.cos_h, s = r.sin_h;
    wi = Vec3d(d.x() * c + d.z() * s, d.y() * c + d.y() * (1.0 - c), d.z() * c - d.x() * s);
    wo = reflect<double>(wi, r.h);
    return wi.z() > 0 && wo.z() > 0;
  }

 private:
  std::vector<Vec3d> d_;
};

}  // namespace

size_t cell_chunk_count(int coarsen) { return size_t(merl::kResThetaH / coarsen * theta_d_blocks(coarsen)); }

double build_cell_chunk(const merl::Table& table, const CellWeighting& weighting, int coarsen, size_t i,
                        MetricChunk& ch) {
  using namespace merl;
  const int k = coarsen;
  const int nd = kResThetaD / k, np = kResPhiD / k, blocks_d = theta_d_blocks(k);
  static const CellDirections directions;
  const int bh = int(i) / blocks_d, bd0 = int(i) % blocks_d * kThetaDBlock;
  const int bd1 = std::min(nd, bd0 + kThetaDBlock);
  ch.clear();
  const size_t most = size_t(bd1 - bd0) * size_t(np) * (weighting.fold ? 1 : 2);
  for (auto* v : {&ch.wi_x, &ch.wi_y, &ch.wi_z, &ch.wo_x, &ch.wo_y, &ch.wo_z, &ch.sqrt_weight, &ch.factor,
                  &ch.measured[0], &ch.measured[1], &ch.measured[2]})
    v->reserve(most);
  const CellDirections::Row row = CellDirections::row(bh * k + k / 2);
  const double h_factor = theta_h_factor(bh * k, bh * k + k), p_factor = phi_d_factor(k);
  double sum = 0;
  for (int bd = bd0; bd < bd1; ++bd) {
    const double d_factor = theta_d_factor(bd * k, bd * k + k);
    for (int bp = 0; bp < np; ++bp) {
      const Cell c{bh * k + k / 2, bd * k + k / 2, bp * k + k / 2};
      const size_t off = cell_offset(c);
      if (!table.valid(off)) continue;
      Vec3d wi, wo;
      if (!directions(row, c.theta_d, c.phi_d, wi, wo)) continue;
      const double mu_io = weighting.density(wi, wo), mu_oi = weighting.density(wo, wi);
      if (!(mu_io > 0 || mu_oi > 0)) continue;
      const double w = block_measure(h_factor, d_factor, p_factor);
      sum += w;
      const Rgb m = table.value(off);
      const double fi = weighting.cos_i_factor ? wi.z() : 1.0, fo = weighting.cos_i_factor ? wo.z() : 1.0;
      if (weighting.fold) {
        ch.push(wi, wo, 0.5 * w * (mu_io * fi * fi + mu_oi * fo * fo), 1.0, m);
      } else {
        if (mu_io > 0) ch.push(wi, wo, 0.5 * w * mu_io, fi, m);
        if (mu_oi > 0) ch.push(wo, wi, 0.5 * w * mu_oi, fo, m);
      }
    }
  }
  return sum;
}

CellDomain build_cell_domain(const merl::Table& table, const CellWeighting& weighting, int coarsen) {
  std::vector<MetricChunk> chunks(cell_chunk_count(coarsen));
  std::vector<double> measure(chunks.size(), 0.0);
  tbb::parallel_for(size_t(0), chunks.size(),
                    [&](size_t i) { measure[i] = build_cell_chunk(table, weighting, coarsen, i, chunks[i]); });
  CellDomain d;
  d.chunks = std::move(chunks);
  for (double s : measure) d.measure_sum += s;  // chunk order: deterministic
  return d;
}

}  // namespace brdfkit::fit
