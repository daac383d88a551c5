#include <gtest/gtest.h>

#include <cmath>

#include "brdfkit/analysis/model_checks.h"
#include "brdfkit/models/lambert.h"
#include "brdfkit/models/microfacet_model.h"
#include "brdfkit/models/model.h"
#include "brdfkit/ndf/beckmann.h"
#include "brdfkit/ndf/ggx.h"

using namespace brdfkit;

TEST(ModelChecks, NormalizationOfBeckmannAndGgx) {
  for (double a : {0.005, 0.05, 0.3, 1.0, 2.0}) {
    const Beckmann<double> b(&a);
    const Ggx<double> g(&a);
    EXPECT_NEAR(ndf_normalization([&](double c) { return b.D(c); }), 1.0, 1e-8) << "Beckmann alpha " << a;
    EXPECT_NEAR(ndf_normalization([&](double c) { return g.D(c); }), 1.0, 1e-8) << "GGX alpha " << a;
  }
  // Sanity: an unnormalized shape is reported as such (∫ cos²θ dω = 2π/3).
  EXPECT_NEAR(ndf_normalization([](double c) { return c; }), 2 * kPi / 3, 1e-10);
}

TEST(ModelChecks, NormalizationOfEveryRegisteredMicrofacetModel) {
  for (const Model* m : all_models()) {
    const auto* view = dynamic_cast<const MicrofacetDistributionView*>(m);
    if (!view) continue;
    const ParamValues v = ParamValues::defaults(m->params());
    EXPECT_NEAR(ndf_normalization([&](double c) { return view->ndf(v.channel(0), c); }), 1.0, 1e-6) << m->name();
  }
}

TEST(ModelChecks, LambertAlbedoIsKd) {
  const ModelAdapter<Lambert> lambert;
  const double kd = 0.63;
  for (double t : albedo_angles_deg()) EXPECT_NEAR(albedo(lambert, &kd, 0, t * kPi / 180), kd, 1e-9) << t;
}

TEST(ModelChecks, AlbedoOfAKnownFunction) {
  // ρ = cosθo/π: a(wi) = ∫ cos²θo/π dω = 2/3 for every wi.
  for (double t : {0.0, 0.7, 1.3})
    EXPECT_NEAR(albedo([](const Vec3d&, const Vec3d& wo) { return wo.z() > 0 ? wo.z() * kInvPi : 0.0; }, t),
                2.0 / 3.0, 1e-9);
}

namespace {
struct NonReciprocal {
  static std::string_view name() { return "non-reciprocal"; }
  static std::string_view description() { return "test double: rho = cos(theta_i)"; }
  static constexpr bool kReciprocal = false;
  static ParamTable params() { return {}; }
  template <class T> static T eval(const T*, int, const Vec3<T>& wi, const Vec3<T>&) { return wi.z(); }
  static std::optional<Vec3d> sample(const double*, int, const Vec3d&, const Vec2d&, double) { return std::nullopt; }
  static double pdf(const double*, int, const Vec3d&, const Vec3d&) { return 0; }
};
}  // namespace

TEST(ModelChecks, ReciprocityCheckSeesAsymmetry) {
  const ModelAdapter<NonReciprocal> m;
  const auto r = reciprocity_check(m, nullptr, 0, 500, 3);
  EXPECT_GT(r.max_relative_error, 0.9);
  EXPECT_EQ(r.pairs, 500);
  const ModelAdapter<Lambert> lambert;
  const double kd = 0.5;
  EXPECT_EQ(reciprocity_check(lambert, &kd, 0).max_relative_error, 0.0);
}
