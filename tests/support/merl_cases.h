#pragma once
// MERL-format materials tabulated from known parameters for the recovery tests: the
// cells a metric with `coarsen` k reads (the middle cell of each k × k × k index block, see
// fit/metric_cells.h) are filled at their centres, every other cell is "not measured". A full
// table (k = 1) costs one model evaluation per cell; k = 3 costs 1/27 of it and the fit reads
// exactly the same cells, so the optimum is still exact.
#include <gtest/gtest.h>

#include <random>
#include <utility>
#include <vector>

#include "brdfkit/measured/merl.h"
#include "brdfkit/measured/merl_brdf.h"
#include "brdfkit/models/model.h"

namespace brdfkit::test {

// A model and the truth its table is tabulated from (parameter name, value per channel).
// Models whose G1 comes from a numeric Λ table (or, for Bagher's SGD, a fitted G1 per shape) cost
// more per evaluation and read fewer cells (larger k), so the executables stay within the CI
// budget; the optimum is exact at any k.
struct RecoveryCase {
  const char* model;
  std::vector<std::pair<const char*, Rgb>> truth;
  int coarsen = 3;  // tabulate_cells k: the table holds 1/k³ of the cells
};

inline ParamValues with(const Model& m, const std::vector<std::pair<const char*, Rgb>>& vals) {
  ParamValues v = ParamValues::defaults(m.params());
  for (const auto& [name, rgb] : vals) {
    const int i = find_param(m.params(), name);
    EXPECT_GE(i, 0) << name;
    if (i < 0) continue;
    for (int c = 0; c < 3; ++c) v.values[size_t(c)][size_t(i)] = rgb[c];
  }
  return v;
}

// missing: fraction of the filled cells then marked not measured; noise: relative size of a
// multiplicative Gaussian perturbation; both seeded.
inline merl::Table tabulate_cells(const Model& m, const ParamValues& v, int k, double missing = 0, double noise = 0,
                                  std::uint64_t seed = 11) {
  const Brdf brdf(m, v);
  merl::Table t;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g(0, 1);
  for (int ih = k / 2; ih < merl::kResThetaH; ih += k)
    for (int id = k / 2; id < merl::kResThetaD; id += k)
      for (int ip = k / 2; ip < merl::kResPhiD; ip += k) {
        const merl::Cell c{ih, id, ip};
        Vec3d wi, wo;
        if (!merl::cell_directions(c, wi, wo)) continue;
        Rgb r = brdf.eval(wi, wo);
        if (noise > 0) r *= 1.0 + noise * g(rng);
        if (missing > 0 && u(rng) < missing) continue;
        t.set_raw(merl::cell_offset(c), r[0] / merl::kScale[0], r[1] / merl::kScale[1], r[2] / merl::kScale[2]);
      }
  return t;
}

}  // namespace brdfkit::test
