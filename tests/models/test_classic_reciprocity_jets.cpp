// Reciprocity (to 1e-10 relative) and Jet evaluation (value equals the double evaluation,
// derivatives equal central differences) of the seed 002 / seed 003 models.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <random>
#include <tuple>

#include "brdfkit/analysis/model_checks.h"
#include "brdfkit/models/ashikhmin_shirley.h"
#include "brdfkit/models/blinn_phong_lobe.h"
#include "brdfkit/models/cook_torrance_anisotropic.h"
#include "brdfkit/models/lafortune.h"
#include "brdfkit/models/low_smooth.h"
#include "brdfkit/models/poulin_fournier.h"
#include "brdfkit/models/ward.h"
#include "brdfkit/models/ward_duer.h"
#include "brdfkit/ndf/beckmann_anisotropic.h"
#include "brdfkit/ndf/ggx_anisotropic.h"
#include "support/catalogue_cases.h"

namespace brdfkit {
namespace {

using test::ModelCase;

std::vector<ModelCase> all_cases() {
  auto v = test::moderate_cases();
  for (auto& c : test::sharp_cases()) v.push_back(c);
  return v;
}

TEST(ClassicModels, AllReciprocalTo1e10) {
  for (const ModelCase& mc : all_cases()) {
    const Model& m = model_by_name(mc.model);
    EXPECT_TRUE(m.reciprocal()) << mc.model;
    const ParamValues v = test::values_of(m, mc);
    const ReciprocityCheck r = reciprocity_check(m, v.channel(0), 0, 2000, 7);
    EXPECT_GT(r.pairs, 1000) << mc.model << " " << mc.label;
    EXPECT_LE(r.max_relative_error, 1e-10) << mc.model << " " << mc.label << " worst wi " << r.wi.transpose()
                                           << " wo " << r.wo.transpose();
  }
}

// Values are zero below the horizon and finite and non-negative above (no NaN at the poles).
TEST(ClassicModels, FiniteNonNegativeEverywhere) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const ModelCase& mc : all_cases()) {
    const Model& m = model_by_name(mc.model);
    const ParamValues v = test::values_of(m, mc);
    const Vec3d n = Vec3d::UnitZ();
    EXPECT_TRUE(std::isfinite(m.eval(v.channel(0), 0, n, n))) << mc.model;
    EXPECT_EQ(m.eval(v.channel(0), 0, Vec3d(0, 0.6, -0.8), n), 0.0) << mc.model;
    for (int k = 0; k < 500; ++k) {
      const Vec3d wi = spherical_direction(std::acos(u(rng)), 2 * kPi * u(rng));
      const Vec3d wo = spherical_direction(std::acos(u(rng)), 2 * kPi * u(rng));
      const double f = m.eval(v.channel(0), 0, wi, wo);
      ASSERT_TRUE(std::isfinite(f) && f >= 0) << mc.model << " " << mc.label << " f = " << f;
    }
  }
}

using Jet = ceres::Jet<double, 12>;

template <class M> void check_jets(const ModelCase& mc) {
  const Model& m = model_by_name(mc.model);
  const ParamValues v = test::values_of(m, mc);
  const size_t np = m.params().size();
  ASSERT_LE(np, 12u);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int compared = 0;
  for (int k = 0; k < 40; ++k) {
    const Vec3d wi = spherical_direction(std::acos(0.05 + 0.95 * u(rng)), 2 * kPi * u(rng));
    const Vec3d wo = spherical_direction(std::acos(0.05 + 0.95 * u(rng)), 2 * kPi * u(rng));
    std::vector<Jet> pj(np);
    std::vector<double> pd(v.values[1]);
    for (size_t i = 0; i < np; ++i) pj[i] = Jet(pd[i], int(i));
    const Vec3<Jet> wij = wi.cast<Jet>(), woj = wo.cast<Jet>();
    const Jet fj = M::template eval<Jet>(pj.data(), 1, wij, woj);
    const double fd = M::template eval<double>(pd.data(), 1, wi, wo);
    ASSERT_NEAR(fj.a, fd, 1e-14 * std::abs(fd)) << mc.model;
    if (!(fd > 1e-8)) continue;
    for (size_t i = 0; i < np; ++i) {
      const double h = 1e-6 * std::max(1.0, std::abs(pd[i]));
      std::vector<double> lo = pd, hi = pd;
      lo[i] -= h;
      hi[i] += h;
      const double fd_diff =
          (M::template eval<double>(hi.data(), 1, wi, wo) - M::template eval<double>(lo.data(), 1, wi, wo)) / (2 * h);
      EXPECT_NEAR(fj.v[int(i)], fd_diff, 1e-5 * (std::abs(fd_diff) + fd / std::max(1.0, std::abs(pd[i]))))
          << mc.model << " " << mc.label << " d/d" << m.params()[i].name;
    }
    ++compared;
  }
  EXPECT_GT(compared, 5) << mc.model << " " << mc.label;
}

using Types = std::tuple<Ward, WardAniso, WardDuer, BlinnPhongLobe, Lafortune, Lafortune2, AshikhminShirley,
                         AshikhminShirleyDielectric, LowSmooth, LowSmooth2, CookTorranceAnisotropic<GgxAnisotropic>,
                         CookTorranceAnisotropic<BeckmannAnisotropic>, PoulinFournier>;

template <size_t I = 0> void dispatch_jets(const ModelCase& mc, int& found) {
  if constexpr (I < std::tuple_size_v<Types>) {
    using M = std::tuple_element_t<I, Types>;
    if (M::name() == mc.model) {
      ++found;
      check_jets<M>(mc);
    }
    dispatch_jets<I + 1>(mc, found);
  }
}

TEST(ClassicModels, JetsEqualDoublesAndFiniteDifferences) {
  for (const ModelCase& mc : test::moderate_cases()) {
    if (mc.label == "tie_N25") continue;  // the kink of max(|Cxy|, |Cz|)
    int found = 0;
    dispatch_jets(mc, found);
    EXPECT_EQ(found, 1) << mc.model;
  }
}

}  // namespace
}  // namespace brdfkit
