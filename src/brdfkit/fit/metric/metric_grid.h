#pragma once
// The sample domain of a metric: a tensor-product grid in (θi, θo, Δφ) with separable quadrature
// weights (every metric of DESIGN.md §7 is one), cut into one chunk per θi node. A chunk is kept
// in structure-of-arrays form with the measured value looked up once, invalid cells dropped.
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "brdfkit/core/pair_arrays.h"
#include "brdfkit/measured/measured_brdf.h"

namespace brdfkit::fit {

// One node of a quadrature axis: its angle (radians) and its weight.
struct AxisNode {
  double angle;
  double weight;
};

struct GridSpec {
  std::vector<AxisNode> theta_i, theta_o, phi;  // φ is φo − φi; wi lies in the xz-plane (φi = 0)
  bool cos_i_factor = false;  // the residual compares cosθi·ρ (seeds 002, 003, 004), not ρ
};

// Samples of one θi node, SoA so evaluation loops vectorize (DESIGN.md §12).
struct MetricChunk : PairArrays {
  std::vector<double> sqrt_weight;  // square root of the quadrature weight
  std::vector<double> factor;       // multiplies ρ (model and measured) before the transform
  std::array<std::vector<double>, 3> measured;
  size_t size() const { return sqrt_weight.size(); }
  // Empties every array, keeping its capacity.
  void clear() {
    for (auto* v : {&wi_x, &wi_y, &wi_z, &wo_x, &wo_y, &wo_z, &sqrt_weight, &factor}) v->clear();
    for (auto& c : measured) c.clear();
  }
  // Appends one sample of quadrature weight `weight` (its square root is kept).
  void push(const Vec3d& wi, const Vec3d& wo, double weight, double f, const Rgb& m) {
    push_pair(wi, wo);
    sqrt_weight.push_back(std::sqrt(weight));
    factor.push_back(f);
    for (int c = 0; c < 3; ++c) measured[size_t(c)].push_back(m[c]);
  }
};

// Midpoint nodes of n equal cells over [lo, hi] (cell centres), each weighted by `scale` × width.
std::vector<AxisNode> cell_centres(double lo, double hi, int n, double scale = 1.0);
// Nodes lo, lo + step, …, up to hi inclusive (within 1e-9 of a step), each weighted by step.
std::vector<AxisNode> regular_nodes(double lo, double hi, double step);

// Builds the chunk of θi node i: looks the measured value up at every (θo, φ) node, keeps the
// valid ones with non-zero weight. Into `out` (its arrays' capacity reused: on-demand grids such
// as hp-rmse's rebuild 81 chunks of 0.46 M nodes per evaluation), or as a new chunk.
void build_chunk(const GridSpec& grid, size_t i, const MeasuredBrdf& data, MetricChunk& out);
MetricChunk build_chunk(const GridSpec& grid, size_t i, const MeasuredBrdf& data);

}  // namespace brdfkit::fit
