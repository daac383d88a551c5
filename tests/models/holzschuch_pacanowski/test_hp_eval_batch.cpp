// HolzschuchPacanowski::eval_batch builds the exponential-power distribution (a long-double
// Γ(1/p)) once per batch instead of once per pair — 15.2 s → 2.7 s user for one recovery fit
// (perf: 65 % of the time was in Boost's tgamma) — and computes D and the G1 table's coordinate
// with vector math; it must give eval's values within ndf/d_block.h's 1e-12 relative, since
// tables are tabulated through eval and fitted through eval_batch. Its three-channel pass
// (eval_batch_rgb: D and G1 once for R, G and B) must equal the channels' eval_batch to the bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "brdfkit/core/warp.h"
#include "brdfkit/models/holzschuch_pacanowski.h"

namespace brdfkit {
namespace {

// Pairs in both hemispheres (some below the horizon), as structure-of-arrays.
struct Pairs {
  std::vector<double> v[6];
  SoaPairs soa() const { return {v[0].data(), v[1].data(), v[2].data(), v[3].data(), v[4].data(), v[5].data()}; }
};

Pairs random_pairs(size_t n) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Pairs p;
  for (auto& a : p.v) a.resize(n);
  for (size_t k = 0; k < n; ++k) {
    // Some pairs below the horizon (value 0) among the upper-hemisphere ones.
    const Vec3d wi = spherical_direction(1.7 * u(rng), 2 * kPi * u(rng));
    const Vec3d wo = spherical_direction(1.6 * u(rng), 2 * kPi * u(rng));
    for (int a = 0; a < 3; ++a) {
      p.v[a][k] = wi[a];
      p.v[3 + a][k] = wo[a];
    }
  }
  return p;
}

TEST(HpEvalBatch, EqualsEvalWithinVectorMathBound) {
  const Model& m = model_by_name("holzschuch-pacanowski");
  const size_t n = 500;
  const Pairs pairs = random_pairs(n);
  const auto& v = pairs.v;
  const SoaPairs d = pairs.soa();
  int compared = 0, below = 0;
  double worst = 0;
  for (const double p_shape : {0.15, 0.6, 1.0, 3.0}) {
    ParamValues values = ParamValues::defaults(m.params());
    values.set(m.params(), "p", p_shape);
    values.set(m.params(), "sigma", 0.2 * p_shape);
    for (int c = 0; c < 3; ++c) {
      std::vector<double> out(n);
      m.eval_batch(values.channel(c), c, n, d, out.data());
      for (size_t k = 0; k < n; ++k, ++compared) {
        const double want =
            m.eval(values.channel(c), c, Vec3d(v[0][k], v[1][k], v[2][k]), Vec3d(v[3][k], v[4][k], v[5][k]));
        if (want == 0) ++below;
        worst = std::max(worst, std::abs(out[k] - want) / std::max(want, 1e-300));
        ASSERT_NEAR(out[k], want, 1e-12 * want) << "p " << p_shape << " channel " << c << " pair " << k;
      }
    }
  }
  std::printf("HP eval_batch: %d values (%d below the horizon) within %.3g relative of eval\n", compared, below,
              worst);
  EXPECT_EQ(compared, 4 * 3 * 500);
  EXPECT_GT(below, 100);
}

TEST(HpEvalBatch, RgbPassEqualsChannelPasses) {
  const Model& m = model_by_name("holzschuch-pacanowski");
  const size_t n = 500;
  const Pairs pairs = random_pairs(n);
  ParamValues values = ParamValues::defaults(m.params());
  const double kd[3] = {0.1, 0.3, 0.02}, ks[3] = {0.8, 0.2, 1.5}, kw[3] = {0.01, 0.2, 0.05}, f0[3] = {0.04, 0.5, 0.9};
  const std::pair<const char*, const double*> colours[] = {{"kd", kd}, {"ks", ks}, {"kw", kw}, {"F0", f0}};
  for (const auto& [name, x] : colours)
    for (int c = 0; c < 3; ++c) values.values[size_t(c)][size_t(find_param(m.params(), name))] = x[c];
  // Shared σ and p (one pass), then a σ of its own in blue (three passes).
  for (const bool shared : {true, false}) {
    if (!shared) values.values[2][size_t(find_param(m.params(), "sigma"))] *= 1.5;
    std::vector<double> rgb[3], one(n);
    for (auto& r : rgb) r.resize(n);
    const double* const p[3] = {values.channel(0), values.channel(1), values.channel(2)};
    double* const out[3] = {rgb[0].data(), rgb[1].data(), rgb[2].data()};
    m.eval_batch_rgb(p, n, pairs.soa(), out);
    for (int c = 0; c < 3; ++c) {
      m.eval_batch(p[c], c, n, pairs.soa(), one.data());
      for (size_t k = 0; k < n; ++k)
        ASSERT_EQ(rgb[c][k], one[k]) << (shared ? "shared" : "per-channel") << " σ, channel " << c << " pair " << k;
    }
  }
}

}  // namespace
}  // namespace brdfkit
