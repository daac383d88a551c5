// HeTorrance::eval_batch keeps what depends on the cosines alone (the shadowing of wi and wo, σ)
// while they repeat, as they do through a metric chunk (one incidence per chunk, Δφ fastest),
// computes it for new cosines eight pairs at a time (he_pair_shape_lanes), and looks the series
// up a block of pairs at a time (HeSeriesTable::block_at): it must give eval's values within the
// table's block bounds (1e-12 relative, 1e-11 where c/g > 1000, as at a smooth, long-correlated
// surface), since tables are tabulated through eval and fits run through eval_batch.
// eval_batch_rgb, which computes the shape terms once for R, G and B (and the Fresnel factor where
// the channels share η and k), must give eval_batch's to the bit. Its eval_batch_from, which fits
// use for differences in η and k, must give eval_batch's values to rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "brdfkit/core/warp.h"
#include "brdfkit/models/he_torrance.h"
#include "brdfkit/models/model.h"

namespace brdfkit {
namespace {

TEST(HeEvalBatch, AgreesWithEvalThroughRunsOfOneIncidence) {
  const Model& m = model_by_name("he");
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> v[6];
  auto push = [&](const Vec3d& wi, const Vec3d& wo) {
    for (int a = 0; a < 3; ++a) {
      v[a].push_back(wi[a]);
      v[3 + a].push_back(wo[a]);
    }
  };
  // Runs of one incidence (some below the horizon, value 0); runs of one incidence and one θo
  // with φ varying (a metric grid's rows); runs of one θo with the incidence varying; then every
  // pair its own incidence.
  for (int run = 0; run < 12; ++run) {
    const Vec3d wi = spherical_direction(1.65 * u(rng), 0.0);
    for (int k = 0; k < 40; ++k) push(wi, spherical_direction(1.65 * u(rng), 2 * kPi * u(rng)));
  }
  for (int run = 0; run < 6; ++run) {
    const Vec3d wi = spherical_direction(1.5 * u(rng), 0.0);
    for (int row = 0; row < 4; ++row) {
      const double theta_o = 1.5 * u(rng);
      for (int k = 0; k < 10; ++k) push(wi, spherical_direction(theta_o, 2 * kPi * u(rng)));
    }
  }
  for (int run = 0; run < 4; ++run) {
    const double theta_o = 1.5 * u(rng);
    for (int k = 0; k < 10; ++k) push(spherical_direction(1.5 * u(rng), 0.0), spherical_direction(theta_o, 2 * kPi * u(rng)));
  }
  for (int k = 0; k < 200; ++k) push(spherical_direction(1.65 * u(rng), 2 * kPi * u(rng)), spherical_direction(1.65 * u(rng), 2 * kPi * u(rng)));
  const size_t n = v[0].size();
  const SoaPairs d{v[0].data(), v[1].data(), v[2].data(), v[3].data(), v[4].data(), v[5].data()};
  int compared = 0, nonzero = 0;
  double worst = 0;
  // The channels share η and k (and so their Fresnel factor, computed once), or differ in them.
  for (const bool shared_index : {true, false})
  for (const auto& [sigma0, tau] :
       {std::pair{0.05, 3.0}, std::pair{0.53, 2.0}, std::pair{1.5, 8.0}, std::pair{0.24, 38.0}}) {
    ParamValues values = ParamValues::defaults(m.params());
    values.set(m.params(), "sigma0", sigma0);
    values.set(m.params(), "tau", tau);
    if (!shared_index) {
      values.values[1][size_t(HeTorrance::kEta)] = 0.4;
      values.values[2][size_t(HeTorrance::kK)] = 2.0;
    }
    std::vector<double> rgb[3] = {std::vector<double>(n), std::vector<double>(n), std::vector<double>(n)};
    const double* p_rgb[3] = {values.channel(0), values.channel(1), values.channel(2)};
    double* out_rgb[3] = {rgb[0].data(), rgb[1].data(), rgb[2].data()};
    m.eval_batch_rgb(p_rgb, n, d, out_rgb);
    for (int c = 0; c < 3; ++c) {
      std::vector<double> out(n);
      m.eval_batch(values.channel(c), c, n, d, out.data());
      for (size_t k = 0; k < n; ++k, ++compared) {
        const double want = m.eval(values.channel(c), c, Vec3d(v[0][k], v[1][k], v[2][k]), Vec3d(v[3][k], v[4][k], v[5][k]));
        ASSERT_EQ(rgb[c][k], out[k]) << "eval_batch_rgb, shared index " << shared_index << ", sigma0 " << sigma0 << " channel " << c << " pair " << k;
        ASSERT_EQ(out[k] == 0, want == 0) << "sigma0 " << sigma0 << " channel " << c << " pair " << k;
        if (want > 0) worst = std::max(worst, std::abs(out[k] / want - 1));
        nonzero += want > 0;
      }
    }
  }
  std::printf("He eval_batch vs eval: worst relative %.3g over %d values\n", worst, compared);
  EXPECT_LT(worst, 1e-11);
  EXPECT_EQ(compared, 2 * 4 * 3 * 960);
  EXPECT_GT(nonzero, compared / 3);  // most pairs above the horizon: the comparison is not of zeros
}

TEST(HeEvalBatch, RgbWithAShapePerChannelEqualsEvalBatchToTheBit) {
  const Model& m = model_by_name("he");
  std::vector<double> v[6];
  for (int k = 0; k < 60; ++k) {
    const Vec3d wi = spherical_direction(0.02 * k, 0.0), wo = spherical_direction(1.5 - 0.02 * k, 0.1 * k);
    for (int a = 0; a < 3; ++a) {
      v[a].push_back(wi[a]);
      v[3 + a].push_back(wo[a]);
    }
  }
  const SoaPairs d{v[0].data(), v[1].data(), v[2].data(), v[3].data(), v[4].data(), v[5].data()};
  ParamValues values = ParamValues::defaults(m.params());
  values.values[1][size_t(HeTorrance::kSigma0)] = 0.9;  // a fit with per-channel shapes
  values.values[2][size_t(HeTorrance::kTau)] = 7.0;
  std::vector<double> rgb[3] = {std::vector<double>(60), std::vector<double>(60), std::vector<double>(60)};
  const double* p_rgb[3] = {values.channel(0), values.channel(1), values.channel(2)};
  double* out_rgb[3] = {rgb[0].data(), rgb[1].data(), rgb[2].data()};
  m.eval_batch_rgb(p_rgb, 60, d, out_rgb);
  for (int c = 0; c < 3; ++c) {
    std::vector<double> out(60);
    m.eval_batch(values.channel(c), c, 60, d, out.data());
    for (size_t k = 0; k < 60; ++k) {
      ASSERT_EQ(rgb[c][k], out[k]) << "channel " << c << " pair " << k;
      const double want = m.eval(values.channel(c), c, Vec3d(v[0][k], v[1][k], v[2][k]), Vec3d(v[3][k], v[4][k], v[5][k]));
      ASSERT_NEAR(out[k], want, 1e-12 * want) << "channel " << c << " pair " << k;
    }
  }
}

TEST(HeEvalBatch, FromAnotherIndexEqualsEvalBatchToRoundingAndRefusesOtherChanges) {
  const Model& m = model_by_name("he");
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> v[6];
  for (int k = 0; k < 500; ++k) {
    const Vec3d wi = spherical_direction(1.65 * u(rng), 0.0), wo = spherical_direction(1.65 * u(rng), 2 * kPi * u(rng));
    for (int a = 0; a < 3; ++a) {
      v[a].push_back(wi[a]);
      v[3 + a].push_back(wo[a]);
    }
  }
  const size_t n = v[0].size();
  const SoaPairs d{v[0].data(), v[1].data(), v[2].data(), v[3].data(), v[4].data(), v[5].data()};
  ParamValues base = ParamValues::defaults(m.params());
  base.set(m.params(), "sigma0", 0.53);
  base.set(m.params(), "tau", 2.0);
  base.set(m.params(), "kd", 0.3);
  // η = 1, k = 0 reflects nothing (F = 0): those pairs are evaluated in full.
  for (const auto& [eta0, k0] : {std::pair{1.5, 0.0}, std::pair{0.9, 0.3}, std::pair{1.0, 0.0}}) {
    ParamValues from = base, to = base;
    from.set(m.params(), "eta", eta0);
    from.set(m.params(), "k", k0);
    to.set(m.params(), "eta", 1.7);
    to.set(m.params(), "k", 0.4);
    for (int c = 0; c < 3; ++c) {
      std::vector<double> at_from(n), want(n), got(n);
      m.eval_batch(from.channel(c), c, n, d, at_from.data());
      m.eval_batch(to.channel(c), c, n, d, want.data());
      ASSERT_TRUE(m.eval_batch_from(to.channel(c), from.channel(c), at_from.data(), c, n, d, got.data()));
      for (size_t k = 0; k < n; ++k)
        ASSERT_NEAR(got[k], want[k], 1e-13 * std::abs(want[k])) << "eta0 " << eta0 << " channel " << c << " pair " << k;
    }
  }
  // Any other parameter changed: the Fresnel ratio does not give it.
  for (const char* name : {"kd", "ks", "sigma0", "tau"}) {
    ParamValues to = base;
    to.set(m.params(), name, 0.7);
    std::vector<double> at_base(n), out(n, -1.0);
    m.eval_batch(base.channel(0), 0, n, d, at_base.data());
    EXPECT_FALSE(m.eval_batch_from(to.channel(0), base.channel(0), at_base.data(), 0, n, d, out.data())) << name;
    EXPECT_EQ(out[0], -1.0) << name << ": nothing written";
  }
}

}  // namespace
}  // namespace brdfkit
