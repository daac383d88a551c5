// Directional albedo (measured/albedo.h): tabulated Lambertian and GGX against analytic values and
// an independent quadrature; reporting of cells not measured.
#include <gtest/gtest.h>

#include <cmath>

#include "brdfkit/measured/albedo.h"
#include "brdfkit/measured/merl_brdf.h"
#include "brdfkit/measured/merl_tabulate.h"
#include "brdfkit/measured/rgl_tensor.h"
#include "brdfkit/measured/summary.h"
#include "support/test_util.h"

using namespace brdfkit;

namespace {

constexpr double kDeg = kPi / 180;

// GGX with α = 0.3, F = 1, uncorrelated Smith G = G1(wi) G1(wo): ρ = D G / (4 cos θi cos θo), with
// D = α²/(π cos⁴θ (α² + tan²θ)²) and Λ = (√(1 + α² tan²θ) − 1)/2 (DESIGN.md §3–4), written here
// so this test does not depend on ndf/.
double ggx(const Vec3d& wi, const Vec3d& wo) {
  constexpr double a2 = 0.3 * 0.3;
  if (wi.z() <= 0 || wo.z() <= 0) return 0;
  const Vec3d h = (wi + wo).normalized();
  auto tan2 = [](double c) { return (1 - c * c) / (c * c); };
  const double c = h.z(), t = a2 + tan2(c);
  const double d = a2 / (kPi * c * c * c * c * t * t);
  auto g1 = [&](double cz) { return 1 / (1 + (std::sqrt(1 + a2 * tan2(cz)) - 1) / 2); };
  return d * g1(wi.z()) * g1(wo.z()) / (4 * wi.z() * wo.z());
}

// Reference: midpoint rule in (θo, φo) on a fine grid (a different quadrature and variable than
// the half-vector Gauss–Legendre rule under test); φo ∈ [0, π] doubled by the symmetry φ → −φ.
double ggx_albedo_midpoint(double theta_i) {
  const Vec3d wi = spherical_direction(theta_i, 0.0);
  const int nt = 1500, np = 750;
  const double dt = (kPi / 2) / nt, dp = kPi / np;
  double sum = 0;
  for (int a = 0; a < nt; ++a) {
    const double t = (a + 0.5) * dt, st = std::sin(t), ct = std::cos(t);
    for (int b = 0; b < np; ++b) {
      const double p = (b + 0.5) * dp;
      sum += ggx(wi, Vec3d(st * std::cos(p), st * std::sin(p), ct)) * ct * st;
    }
  }
  return 2 * sum * dt * dp;
}

}  // namespace

TEST(Albedo, AnalyticLambertian) {
  for (int deg = 0; deg <= 85; deg += 5) {
    const DirectionalAlbedo a =
        directional_albedo([](const Vec3d&, const Vec3d&) -> Rgb { return Rgb::Constant(0.5 * kInvPi); }, deg * kDeg);
    EXPECT_NEAR(a.value[0], 0.5, 2e-4) << deg;
    EXPECT_EQ(a.missing_fraction, 0.0);
  }
}

TEST(Albedo, TabulatedLambertianIsHalfAtEveryAngle) {
  const MerlBrdf brdf(merl::tabulate([](const Vec3d&, const Vec3d&) -> Rgb { return Rgb::Constant(0.5 * kInvPi); }),
                      "lambert-0.5");
  for (int deg = 0; deg <= 80; deg += 10) {
    const auto a = directional_albedo(brdf, deg * kDeg);
    ASSERT_TRUE(a.has_value());
    std::printf("theta_i %2d: albedo %.5f %.5f %.5f, missing %.4f %%\n", deg, a->value[0], a->value[1], a->value[2],
                100 * a->missing_fraction);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a->value[c], 0.5, 0.005) << deg;
  }
}

TEST(Albedo, TabulatedGgxMatchesIndependentIntegral) {
  const MerlBrdf brdf(merl::tabulate([](const Vec3d& wi, const Vec3d& wo) -> Rgb { return Rgb::Constant(ggx(wi, wo)); }),
                      "ggx-0.3");
  for (int deg = 0; deg <= 80; deg += 10) {
    const double ref = ggx_albedo_midpoint(deg * kDeg);
    const auto tab = directional_albedo(brdf, deg * kDeg);
    const DirectionalAlbedo ana =
        directional_albedo([](const Vec3d& wi, const Vec3d& wo) -> Rgb { return Rgb::Constant(ggx(wi, wo)); }, deg * kDeg);
    ASSERT_TRUE(tab.has_value());
    std::printf("theta_i %2d: midpoint %.5f  quadrature of the model %.5f  of the MERL table %.5f (%+.3f %%), "
                "missing %.3f %%\n",
                deg, ref, ana.value[0], tab->value[0], 100 * (tab->value[0] / ref - 1), 100 * tab->missing_fraction);
    EXPECT_NEAR(ana.value[0] / ref, 1.0, 1e-3) << deg;
    EXPECT_NEAR(tab->value[0] / ref, 1.0, 0.01) << deg;
  }
}

// Every other θh row not measured (odd iθh; not a φd range: at θi = 0 every pair has φd = 0 or π):
// the albedo covers the rest, and the missing share
// is reported: albedo + missing·0.5 ≈ 0.5 for a Lambertian 0.5/π.
TEST(Albedo, ReportsCellsNotMeasured) {
  merl::Table t = merl::tabulate([](const Vec3d&, const Vec3d&) -> Rgb { return Rgb::Constant(0.5 * kInvPi); });
  for (size_t k = 0; k < merl::kCellCount; ++k)
    if (merl::cell_at(k).theta_h % 2 == 1) t.set_raw(k, -1, -1, -1);
  const MerlBrdf brdf(std::move(t), "half");
  for (int deg : {0, 40, 80}) {
    const auto a = directional_albedo(brdf, deg * kDeg);
    ASSERT_TRUE(a.has_value());
    std::printf("theta_i %2d: albedo %.4f missing %.4f\n", deg, a->value[0], a->missing_fraction);
    EXPECT_GT(a->missing_fraction, 0.3);
    EXPECT_LT(a->missing_fraction, 0.7);
    EXPECT_NEAR(a->value[0] + 0.5 * a->missing_fraction, 0.5, 0.005);
  }
}

namespace {
// Data that answer nowhere (like scattered samples): no albedo at all.
struct Nowhere final : MeasuredBrdf {
  std::string format() const override { return "none"; }
  std::string path() const override { return "none"; }
  std::string dimensions() const override { return "0"; }
  std::optional<Rgb> eval(const Vec3d&, const Vec3d&) const override { return std::nullopt; }
  SampleSet samples() const override { return {}; }
};
}  // namespace

TEST(Albedo, NoValueWhenTheDataAnswerNowhere) { EXPECT_FALSE(directional_albedo(Nowhere{}, 0.3).has_value()); }

// On real RGL measurements the half-vector quadrature of eval() agrees with RglBrdf::albedo, an
// independent rule (midpoint in the unit square of the VNDF warp, measured/rgl_tensor.h).
TEST(Albedo, RglAgreesWithWarpedMidpointRule) {
  BRDFKIT_REQUIRE_DATA("rgl");
  for (const char* name : {"paper_white_rgb.bsdf", "satin_rosaline_rgb.bsdf", "vch_golden_yellow_rgb.bsdf"}) {
    const RglBrdf brdf(test::data_dir() / "rgl" / name);
    for (int deg = 0; deg <= 80; deg += 20) {
      const auto a = directional_albedo(brdf, deg * kDeg);
      ASSERT_TRUE(a.has_value());
      const Rgb ref = brdf.albedo(spherical_direction(deg * kDeg, 0.0));
      std::printf("%s theta_i %2d: Y %.4f (half-vector quadrature) vs %.4f (warped midpoint)\n", name, deg,
                  luminance(a->value), luminance(ref));
      EXPECT_EQ(a->missing_fraction, 0.0);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(a->value[c] / ref[c], 1.0, 0.01) << name << " " << deg << " " << c;
    }
  }
}
