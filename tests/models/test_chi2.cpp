#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "brdfkit/analysis/chi2_test.h"
#include "brdfkit/core/warp.h"
#include "brdfkit/models/cook_torrance_catalogue.h"
#include "brdfkit/models/model.h"
#include "brdfkit/models/lobe_mixture.h"
#include "support/chi2_width.h"
#include "support/param_sets.h"

using namespace brdfkit;

namespace {
// Incidence angles of the sampling tests, grazing included (θo = 85°).
const double kThetaODeg[] = {0, 40, 85};
constexpr long kSamples = 30000;  // ~60 draws per cell of the 20 × 40 grid: keeps ~200 tests fast
// Parameter values are the same in the three channels of every parameter set below, so one
// channel (green) stands for all.
constexpr int kChannel = 1;
}  // namespace

TEST(Chi2Harness, AcceptsCosineHemisphere) {
  Chi2Options o;
  o.samples = kSamples;
  const auto r = chi2_test([](const Vec2d& u, double) { return std::optional(square_to_cosine_hemisphere(u)); },
                           [](const Vec3d& w) { return cosine_hemisphere_pdf(w); }, o);
  EXPECT_TRUE(r.passed) << r.message;
  EXPECT_NEAR(r.pdf_integral, 1.0, 1e-6);
  EXPECT_EQ(r.rejected_fraction, 0.0);
  EXPECT_GT(r.dof, 100);
}

TEST(Chi2Harness, RejectsAWrongShape) {
  // Uniform-hemisphere pdf 1/(2π) for cosine-distributed draws: same integral, wrong shape.
  Chi2Options o;
  o.samples = kSamples;
  const auto r = chi2_test([](const Vec2d& u, double) { return std::optional(square_to_cosine_hemisphere(u)); },
                           [](const Vec3d& w) { return w.z() > 0 ? 0.5 * kInvPi : 0.0; }, o);
  EXPECT_FALSE(r.passed);
  EXPECT_TRUE(r.integral_passed);  // the integral alone cannot see a wrong shape
  EXPECT_LT(r.p_value, 1e-10);
}

TEST(Chi2Harness, AccountsForRejectedDraws) {
  // Half of the draws rejected; the pdf integrates to 1/2: consistent, so it passes …
  Chi2Options o;
  o.samples = kSamples;
  auto sampler = [](const Vec2d& u, double ul) -> std::optional<Vec3d> {
    if (ul < 0.5) return std::nullopt;
    return square_to_cosine_hemisphere(u);
  };
  auto r = chi2_test(sampler, [](const Vec3d& w) { return 0.5 * cosine_hemisphere_pdf(w); }, o);
  EXPECT_TRUE(r.passed) << r.message;
  EXPECT_NEAR(r.rejected_fraction, 0.5, 0.01);
  EXPECT_NEAR(r.pdf_integral, 0.5, 1e-6);
  // … and a pdf that ignores the rejections fails both tests.
  r = chi2_test(sampler, [](const Vec3d& w) { return cosine_hemisphere_pdf(w); }, o);
  EXPECT_FALSE(r.passed);
  EXPECT_FALSE(r.integral_passed);
}

// Every registered model, at its defaults and with rough and sharp lobe shapes, at normal,
// oblique and grazing viewing. Šidák-corrected over the family so the whole suite has a 1 %
// false-alarm rate.
TEST(Chi2, EveryRegisteredModelSamplesItsPdf) {
  int family = 0;
  for (const Model* m : all_models()) family += int(test::model_param_sets(*m).size()) * int(std::size(kThetaODeg));
  double min_p = 1;
  for (const Model* m : all_models()) {
    for (const auto& set : test::model_param_sets(*m)) {
      for (double t : kThetaODeg) {
        Chi2Options o;
        o.samples = kSamples;
        o.seed = 1000 + unsigned(t);
        o.test_count = family;
        o.quadrature_tol = 1e-6;
        const auto r =
            chi2_test(*m, set.values.channel(kChannel), kChannel, spherical_direction(t * kPi / 180, 0.3), o);
        EXPECT_TRUE(r.passed) << m->name() << " " << set.label << " theta_o " << t << ": " << r.message;
        EXPECT_LE(r.pdf_integral, 1 + 1e-4) << m->name();
        min_p = std::min(min_p, r.p_value);
      }
    }
  }
  std::printf("%d chi2 tests, smallest p-value %.4g\n", family, min_p);
}

// The same tests with the pdf deliberately doubled must fail.
TEST(Chi2, FailsWithPdfTimesTwo) {
  for (const Model* m : all_models()) {
    const ParamValues v = ParamValues::defaults(m->params());
    for (double t : kThetaODeg) {
      const Vec3d wo = spherical_direction(t * kPi / 180, 0.3);
      Chi2Options o;
      o.samples = 20000;
      const auto r = chi2_test([&](const Vec2d& u, double ul) { return m->sample(v.channel(0), 0, wo, u, ul); },
                               [&](const Vec3d& wi) { return 2 * m->pdf(v.channel(0), 0, wo, wi); }, o);
      EXPECT_FALSE(r.passed) << m->name() << " theta_o " << t;
      EXPECT_NEAR(r.pdf_integral, 2 * (1 - r.rejected_fraction), 0.02) << m->name();
    }
  }
}

// A subtler error must fail as well: the half-vector Jacobian written 1/(2 |wo·h|) instead of
// 1/(4 |wo·h|) in the specular part of the mixture.
TEST(Chi2, FailsWithAWrongJacobian) {
  using M = CookTorranceGgx;
  const ParamValues v = ParamValues::defaults(M::params());
  const double* p = v.channel(0);
  const Vec3d wo = spherical_direction(0.7, 0.0);
  Chi2Options o;
  o.samples = kSamples;
  const auto r = chi2_test([&](const Vec2d& u, double ul) { return M::sample(p, 0, wo, u, ul); },
                           [&](const Vec3d& wi) {
                             const double ps = M::specular_probability(p, wo);
                             const Vec3d h = (wi + wo).normalized();
                             return wi.z() > 0 ? (1 - ps) * wi.z() * kInvPi +
                                                     ps * Ggx<double>(p + 2).pdf(h) / (2 * wo.dot(h))
                                               : 0.0;
                           },
                           o);
  EXPECT_FALSE(r.passed);
}

// Power of the sampling test: every model's sampler with its lobe 5 % wider than the density it
// is checked against (tests/support/chi2_width.h) must be rejected, and the model's own sampler,
// with the same draws, must pass; a sampler or pdf whose width is off by 5 % fails here. The
// density is scaled by ∫pdf_wide / ∫pdf (the wider lobe loses more below the horizon), so its
// integral matches the wider sampler's rejections and only the histogram's shape can tell them
// apart: the integral test must pass. On the lobe alone, at θo = 30°.
namespace {
const double kPowerThetaO = 30 * kPi / 180;
constexpr double kWider = 1.05;

std::string test_name(const testing::TestParamInfo<const Model*>& info) {
  std::string s(info.param->name());
  for (char& ch : s)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return s;
}
}  // namespace

class Chi2Power : public testing::TestWithParam<const Model*> {};

TEST_P(Chi2Power, RejectsALobe5PercentWider) {
  const Model& m = *GetParam();
  const test::PowerCase* pc = test::power_case(m.name());
  ASSERT_NE(pc, nullptr) << m.name() << ": name its width parameters in tests/support/chi2_width.h";
  const ParamValues v = test::power_values(m, *pc), w = test::widened(m, *pc, v, kWider);
  const double *p = v.channel(kChannel), *pw = w.channel(kChannel);
  const Vec3d wo = spherical_direction(kPowerThetaO, 0.3);
  const double k = test::widened_cosine_exponent(kWider);  // the Lambertian lobe's control
  const bool lambertian = pc->width.empty();
  auto wide_sample = [&](const Vec2d& u, double ul) -> std::optional<Vec3d> {
    if (lambertian) return lobes::sample_cosine_power(k, u);
    return m.sample(pw, kChannel, wo, u, ul);
  };
  auto wide_pdf = [&](const Vec3d& wi) {
    return lambertian ? lobes::cosine_power_pdf(k, wi.z()) : m.pdf(pw, kChannel, wo, wi);
  };

  Chi2Options o;
  o.samples = pc->draws;
  o.seed = 30;
  o.test_count = int(all_models().size());
  o.quadrature_tol = 1e-6;
  const Chi2Result genuine = chi2_test(m, p, kChannel, wo, o);
  EXPECT_TRUE(genuine.passed) << genuine.message;
  const double scale = test::hemisphere_integral(wide_pdf) / genuine.pdf_integral;
  const Chi2Result wide =
      chi2_test(wide_sample, [&](const Vec3d& wi) { return scale * m.pdf(p, kChannel, wo, wi); }, o);
  const double level = 1 - std::pow(1 - o.significance, 1.0 / o.test_count);
  EXPECT_TRUE(wide.integral_passed) << "the control must leave the pdf integral consistent: " << wide.message;
  EXPECT_LT(wide.p_value, level) << "a lobe 5 % wider passes: " << wide.message;
  std::printf("%-32s %6ld draws: p = %.3g as sampled, %.3g 5 %% wider (level %.3g; integral z %.2f, rejected %.4f)\n",
              std::string(m.name()).c_str(), pc->draws, genuine.p_value, wide.p_value, level, wide.integral_z,
              wide.rejected_fraction);
}

// The models whose sampler costs ~1 ms a draw (test::PowerCase::slow_sampler) run on request:
//   brdfkit_models_tests --gtest_also_run_disabled_tests --gtest_filter='*SlowSamplers/Chi2Power*'
// (their own samplers are also checked by Chi2.EveryRegisteredModelSamplesItsPdf).
namespace {
std::vector<const Model*> power_models(bool slow) {
  std::vector<const Model*> out;
  for (const Model* m : all_models()) {
    const test::PowerCase* pc = test::power_case(m->name());
    if ((pc && pc->slow_sampler) == slow) out.push_back(m);
  }
  return out;
}
}  // namespace
INSTANTIATE_TEST_SUITE_P(EveryModel, Chi2Power, testing::ValuesIn(power_models(false)), test_name);
INSTANTIATE_TEST_SUITE_P(DISABLED_SlowSamplers, Chi2Power, testing::ValuesIn(power_models(true)), test_name);
