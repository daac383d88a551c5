#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

#include "brdfkit/analysis/chi2_test.h"
#include "brdfkit/core/warp.h"
#include "brdfkit/models/cook_torrance_catalogue.h"
#include "brdfkit/models/model.h"
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
