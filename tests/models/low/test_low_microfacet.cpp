// Löw et al. 2012's ABC microfacet model (seed 003 Eq. 15, sampling Eq. 23–28) against a
// separate transcription of the paper's equations in half/difference angles, the printed
// normalization M_h (Eq. 24) and inversion (Eq. 25, both branches and the C ≈ 1 fallback), and
// the energy behaviour the paper reports (albedo rising towards grazing) on its published fits.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <random>

#include "brdfkit/core/half_diff.h"
#include "brdfkit/models/low_microfacet.h"
#include "brdfkit/models/published_fits.h"
#include "support/mc_albedo.h"
#include "support/test_util.h"

namespace brdfkit {
namespace {

// Unpolarized dielectric reflectance from Snell's law and the s/p amplitudes (Born & Wolf), not
// the Cook-Torrance form the model uses.
double fresnel_snell(double cos_i, double eta) {
  const double sin_t = std::sqrt(1 - cos_i * cos_i) / eta;
  const double cos_t = std::sqrt(1 - sin_t * sin_t);
  const double rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  const double rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return 0.5 * (rs * rs + rp * rp);
}

struct LowParams {
  double kd, A, B, C, eta;
};

// Seed 003 Eq. 15 in the angles it is written in: θh, θd, θi, θo; Cook & Torrance's V-groove
// G = min(1, 2 cosθh cosθo/(V·H), 2 cosθh cosθi/(V·H)) with V·H = cosθd.
double paper_eq15(const LowParams& p, double theta_h, double theta_d, double cos_i, double cos_o) {
  const double s = p.A / std::pow(1 + p.B * (1 - std::cos(theta_h)), p.C);
  const double f = fresnel_snell(std::cos(theta_d), p.eta);
  const double k = 2 * std::cos(theta_h) / std::cos(theta_d);
  const double g = std::min({1.0, k * cos_o, k * cos_i});
  return p.kd / kPi + s * f * g / (cos_i * cos_o);
}

ParamValues values(const Model& m, const LowParams& p) {
  ParamValues v = ParamValues::defaults(m.params());
  const std::pair<const char*, double> set[] = {{"kd", p.kd}, {"A", p.A}, {"B", p.B}, {"C", p.C}, {"eta", p.eta}};
  for (const auto& [name, value] : set) v.set(m.params(), name, value);
  return v;
}

TEST(LowMicrofacet, MatchesPaperEq15InHalfDiffAngles) {
  const Model& m = model_by_name("low-microfacet");
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> u(0, 1);
  const LowParams sets[] = {{0.0245, 51.71455 / kPi, 10482.133785, 0.816737, 2.23652},  // alum-bronze E2 (R)
                            {0.3, 2.0, 40.0, 1.0, 1.3},
                            {0.0, 10.0, 1e5, 2.2, 9.0},
                            {0.1, 0.5, 3.0, 0.3, 1.05}};
  double worst = 0;
  int n = 0;
  for (const auto& p : sets) {
    const ParamValues v = values(m, p);
    for (int k = 0; k < 400; ++k) {
      const HalfDiff hd{std::acos(u(rng)) * 0.999, 2 * kPi * u(rng), std::acos(u(rng)) * 0.999, 2 * kPi * u(rng)};
      Vec3d wi, wo;
      from_half_diff(hd, wi, wo);
      if (!(wi.z() > 1e-3 && wo.z() > 1e-3)) continue;
      const double want = paper_eq15(p, hd.theta_h, hd.theta_d, wi.z(), wo.z());
      const double got = m.eval(v.channel(0), 0, wi, wo);
      worst = std::max(worst, std::abs(got - want) / want);
      ++n;
    }
  }
  EXPECT_GT(n, 500);
  EXPECT_LT(worst, 1e-10);
  RecordProperty("worst_relative_difference", std::to_string(worst));
  std::cout << "[ eq15     ] " << n << " pairs, worst relative difference " << worst << "\n";
}

TEST(LowMicrofacet, NormalIncidenceAndMirror) {
  const Model& m = model_by_name("low-microfacet");
  const ParamValues v = values(m, {0.2, 3.0, 500.0, 0.8, 1.5});
  const Vec3d n = Vec3d::UnitZ();
  // θh = θd = 0, G = 1: ρ = kd/π + A ((η − 1)/(η + 1))² = 0.2/π + 3 · 0.04.
  EXPECT_NEAR(m.eval(v.channel(0), 0, n, n), 0.2 / kPi + 3.0 * 0.04, 1e-15);
  // Mirror pair at θ = 1 rad: θh = 0, θd = 1, G = min(1, 2 cos 1 · cos 1 / cos 1) = 1 (2 cos 1 = 1.08).
  const Vec3d wo = spherical_direction(1.0, 0.4), wi = spherical_direction(1.0, 0.4 + kPi);
  const double c = std::cos(1.0);
  EXPECT_NEAR(m.eval(v.channel(0), 0, wi, wo), 0.2 / kPi + 3.0 * fresnel_snell(c, 1.5) / (c * c), 1e-12);
}

// Seed 003 Eq. 24 as printed: M_h = B(C − 1)/(2πA(1 − (1 + B)^{1−C})) for C ≠ 1 and
// B/(2πA ln(1 + B)) for C = 1 make M_h·A·S a density over solid angle (checked by quadrature).
TEST(LowMicrofacet, Eq24NormalizesTheHalfVectorDensity) {
  using Gk = boost::math::quadrature::gauss_kronrod<double, 61>;
  const double A = 2.5;
  for (double B : {0.5, 30.0, 1e4}) {
    for (double C : {0.3, 1.0, 1.7}) {
      const double mh = C == 1.0 ? B / (2 * kPi * A * std::log1p(B))
                                 : B * (C - 1) / (2 * kPi * A * (1 - std::pow(1 + B, 1 - C)));
      // ∫ S dω = 2π ∫₀¹ A (1 + B(1 − c))^{−C} dc, split where the peak at c = 1 narrows.
      auto s = [&](double c) { return A / std::pow(1 + B * (1 - c), C); };
      double integral = 0;
      double lo = 0;
      for (double edge : {1 - 1e-1, 1 - 1e-2, 1 - 1e-3, 1 - 1e-4, 1.0}) {
        integral += Gk::integrate(s, lo, edge, 15, 1e-13);
        lo = edge;
      }
      EXPECT_NEAR(mh * 2 * kPi * integral, 1.0, 1e-9) << "B " << B << " C " << C;
      // The model's sampler uses the same density (AbcFacet::pdf_paper).
      const double p[3] = {A, B, C};
      EXPECT_NEAR(AbcFacet<double>(p).pdf_paper(Vec3d::UnitZ()), mh * A, 1e-12 * mh * A) << "B " << B << " C " << C;
    }
  }
}

// Seed 003 Eq. 25 as printed, both branches:
//   C = 1: θh = arccos(1 − (exp(ξ ln(1 + B)) − 1)/B)
//   C ≠ 1: θh = arccos(1 + (1 − (1 + ξ((1 + B)^{1−C} − 1))^{1/(1−C)})/B)
double eq25_c1(double B, double xi) { return std::acos(1 - (std::exp(xi * std::log(1 + B)) - 1) / B); }
double eq25_c(double B, double C, double xi) {
  return std::acos(1 + (1 - std::pow(1 + xi * (std::pow(1 + B, 1 - C) - 1), 1 / (1 - C))) / B);
}
double sampled_theta(double B, double C, double xi) {
  const double p[3] = {1.0, B, C};
  return std::acos(AbcFacet<double>(p).sample_paper(Vec2d(xi, 0.3)).z());
}

TEST(LowMicrofacet, Eq25BranchesAndNearOneFallback) {
  for (double B : {3.0, 500.0, 2e5}) {
    for (double xi : {0.01, 0.3, 0.7, 0.99}) {
      EXPECT_NEAR(sampled_theta(B, 1.0, xi), eq25_c1(B, xi), 1e-7) << B << " " << xi;
      for (double C : {0.4, 0.9, 1.1, 2.5})
        EXPECT_NEAR(sampled_theta(B, C, xi), eq25_c(B, C, xi), 1e-7) << B << " " << C << " " << xi;
    }
  }
  // C = 1 + 1e-12: the printed C ≠ 1 branch loses digits ((1 + B)^{1−C} − 1 ≈ −1e-11, then the
  // power 1/(1 − C) = −1e12 amplifies its rounding); seed 003 §4 draws from the C = 1 branch
  // there. brdfkit's sampler takes the C = 1 branch and stays within 1e-9 of it.
  double worst_printed = 0, worst_ours = 0;
  for (double xi : {0.1, 0.5, 0.9}) {
    const double ref = eq25_c1(2e5, xi);
    worst_printed = std::max(worst_printed, std::abs(eq25_c(2e5, 1 + 1e-12, xi) - ref));
    worst_ours = std::max(worst_ours, std::abs(sampled_theta(2e5, 1 + 1e-12, xi) - ref));
  }
  std::cout << "[ eq25     ] C = 1 + 1e-12, B = 2e5: printed C != 1 branch off by " << worst_printed
            << " rad, brdfkit's sampler by " << worst_ours << " rad\n";
  EXPECT_LT(worst_ours, 1e-9);
}

// Every material of Löw's published microfacet fits (E2): finite, non-negative values over a
// grid of direction pairs up to grazing (what tabulating them into MERL files needs).
TEST(LowMicrofacet, PublishedFitsFiniteNonNegative) {
  BRDFKIT_REQUIRE_DATA("published-fits");
  const auto fits = PublishedFits::read(test::data_dir() / "published-fits" / "low2012-microfacet-E2.json");
  ASSERT_TRUE(fits.supported()) << fits.unsupported_reason();
  ASSERT_EQ(fits.materials().size(), 100u);
  for (const auto& mat : fits.materials()) {
    const Brdf b = fits.brdf(mat);
    EXPECT_EQ(b.model().name(), "low-microfacet");
    for (int i = 0; i <= 10; ++i)
      for (int o = 0; o <= 10; ++o)
        for (int f = 0; f < 6; ++f) {
          const double ti = i * 0.1 * kPi / 2 * 0.99999, to = o * 0.1 * kPi / 2 * 0.99999;
          const Rgb r = b.eval(spherical_direction(ti, 0.0), spherical_direction(to, f * kPi / 5));
          ASSERT_TRUE(r.isFinite().all() && (r >= 0).all()) << mat << " " << r.transpose();
        }
  }
}

// Seed 003 §5.3: "The new microfacet model has an increase in reflectance near grazing". The
// published fits' albedo (luminance, own sampler, 64² stratified draws) at θ = 30°, 60°, 85°, 89°:
// it rises from 60° to 89° for most materials; the numbers are printed.
TEST(LowMicrofacet, PublishedFitsAlbedoRisesTowardsGrazing) {
  BRDFKIT_REQUIRE_DATA("published-fits");
  const auto fits = PublishedFits::read(test::data_dir() / "published-fits" / "low2012-microfacet-E2.json");
  int rising = 0, above1_85 = 0, above1_89 = 0, above1_60 = 0;
  double max89 = 0;
  std::string max_mat;
  for (const auto& mat : fits.materials()) {
    const Brdf b = fits.brdf(mat);
    auto y = [&](double deg) {
      double a[3];
      for (int c = 0; c < 3; ++c) a[c] = test::mc_albedo(b.model(), b.values().channel(c), c, deg * kPi / 180, 64);
      return test::luminance(a[0], a[1], a[2]);
    };
    const double y60 = y(60), y85 = y(85), y89 = y(89);
    ASSERT_TRUE(std::isfinite(y89)) << mat;
    rising += y89 > y60;
    above1_60 += y60 > 1;
    above1_85 += y85 > 1;
    above1_89 += y89 > 1;
    if (y89 > max89) max89 = y89, max_mat = mat;
  }
  std::cout << "[ grazing  ] albedo(89) > albedo(60) for " << rising << " of 100; albedo > 1 at 60/85/89 deg: "
            << above1_60 << "/" << above1_85 << "/" << above1_89 << "; max at 89 deg " << max89 << " (" << max_mat
            << ")\n";
  RecordProperty("rising", rising);
  RecordProperty("above1_89", above1_89);
  // Measured: rising for 90 of 100, none above 1 (largest 0.71, white-fabric, at 89°): the
  // published fits stay below 1; albedo > 1 needs a large A ∫S (tests AlbedoFiniteAtParameterBounds).
  EXPECT_GE(rising, 80);
  EXPECT_EQ(above1_89, 0);
  EXPECT_EQ(above1_60, 0);
}

}  // namespace
}  // namespace brdfkit
