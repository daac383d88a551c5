// HeTorrance::eval_batch keeps wi's slope terms (an erfc and an exp) while wi.z repeats, as it
// does through a metric chunk (one incidence per chunk), and must give eval's values to the bit:
// tables are tabulated through eval and fits run through eval_batch.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "brdfkit/core/warp.h"
#include "brdfkit/models/he_torrance.h"
#include "brdfkit/models/model.h"

namespace brdfkit {
namespace {

TEST(HeEvalBatch, EqualsEvalToTheBitThroughRunsOfOneIncidence) {
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
  // Runs of one incidence (some below the horizon, value 0), then every pair its own incidence.
  for (int run = 0; run < 12; ++run) {
    const Vec3d wi = spherical_direction(1.65 * u(rng), 0.0);
    for (int k = 0; k < 40; ++k) push(wi, spherical_direction(1.65 * u(rng), 2 * kPi * u(rng)));
  }
  for (int k = 0; k < 200; ++k) push(spherical_direction(1.65 * u(rng), 2 * kPi * u(rng)), spherical_direction(1.65 * u(rng), 2 * kPi * u(rng)));
  const size_t n = v[0].size();
  const SoaPairs d{v[0].data(), v[1].data(), v[2].data(), v[3].data(), v[4].data(), v[5].data()};
  int compared = 0, nonzero = 0;
  for (const auto& [sigma0, tau] : {std::pair{0.05, 3.0}, std::pair{0.53, 2.0}, std::pair{1.5, 8.0}}) {
    ParamValues values = ParamValues::defaults(m.params());
    values.set(m.params(), "sigma0", sigma0);
    values.set(m.params(), "tau", tau);
    for (int c = 0; c < 3; ++c) {
      std::vector<double> out(n);
      m.eval_batch(values.channel(c), c, n, d, out.data());
      for (size_t k = 0; k < n; ++k, ++compared) {
        const double want = m.eval(values.channel(c), c, Vec3d(v[0][k], v[1][k], v[2][k]), Vec3d(v[3][k], v[4][k], v[5][k]));
        ASSERT_EQ(out[k], want) << "sigma0 " << sigma0 << " channel " << c << " pair " << k;
        nonzero += want > 0;
      }
    }
  }
  EXPECT_EQ(compared, 3 * 3 * 680);
  EXPECT_GT(nonzero, compared / 3);  // most pairs above the horizon: the comparison is not of zeros
}

}  // namespace
}  // namespace brdfkit
