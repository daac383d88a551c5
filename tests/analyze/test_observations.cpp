// Observations on synthetic materials whose answer is known: Fresnel extraction (seed 000 Eq. 10)
// returns the Schlick curve a Cook-Torrance material was made with; the diffraction test (seed 004
// §4.2) classifies a pure function of f as diffraction-dominated and a pure function of θh mostly
// not; the back-scattering fit (seed 000 Eq. 7, 12) recovers the family and parameter of its data.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "brdfkit/analysis/albedo_curve.h"
#include "brdfkit/analysis/backscatter.h"
#include "brdfkit/analysis/diffraction_map.h"
#include "brdfkit/analysis/fresnel_extraction.h"
#include "brdfkit/core/error.h"
#include "brdfkit/core/half_diff.h"
#include "brdfkit/models/model.h"
#include "brdfkit/ndf/ggx.h"
#include "test_util.h"

namespace brdfkit {
namespace {

// A measured BRDF given by a function (exact values anywhere above the horizon).
class FunctionBrdf final : public MeasuredBrdf {
 public:
  explicit FunctionBrdf(std::function<Rgb(const Vec3d&, const Vec3d&)> f) : f_(std::move(f)) {}
  std::string format() const override { return "analytic"; }
  std::string path() const override { return "synthetic"; }
  std::string dimensions() const override { return "continuous"; }
  std::optional<Rgb> eval(const Vec3d& wi, const Vec3d& wo) const override {
    if (!(wi.z() > 0 && wo.z() > 0)) return std::nullopt;
    return f_(wi, wo);
  }
  SampleSet samples() const override { return {}; }

 private:
  std::function<Rgb(const Vec3d&, const Vec3d&)> f_;
};

const Model& ggx_model() { return model_by_name("cook-torrance-ggx"); }

ParamValues ggx_values(double alpha) {
  const Model& m = ggx_model();
  ParamValues v = ParamValues::defaults(m.params());
  v.set(m.params(), "kd", 0.1);
  v.set(m.params(), "ks", 0.8);
  v.set(m.params(), "alpha", alpha);
  v.set(m.params(), "F0", 0.04, 0);
  v.set(m.params(), "F0", 0.06, 1);
  v.set(m.params(), "F0", 0.1, 2);
  return v;
}

FunctionBrdf material(const ParamValues& v) {
  return FunctionBrdf([v](const Vec3d& wi, const Vec3d& wo) {
    Rgb r;
    for (int c = 0; c < 3; ++c) r[c] = ggx_model().eval(v.channel(c), c, wi, wo);
    return r;
  });
}

TEST(FresnelExtraction, ReturnsTheSchlickCurveOfASyntheticMaterial) {
  const ParamValues v = ggx_values(0.2);
  const FunctionBrdf data = material(v);
  const auto curve = analysis::extract_fresnel(data, ggx_model(), v);
  double worst = 0;
  for (size_t k = 0; k < curve.theta_d.size(); ++k) {
    if (!curve.reliable[k]) continue;
    ASSERT_TRUE(curve.has_data[k]);
    for (int c = 0; c < 3; ++c) {
      const double f0 = v.values[size_t(c)][3];
      const double m = 1 - std::cos(curve.theta_d[k]);
      const double schlick = f0 + (1 - f0) * m * m * m * m * m;
      worst = std::max(worst, std::abs(curve.data[k][c] / schlick - 1));
      EXPECT_NEAR(curve.data[k][c], curve.model[k][c], 1e-12);
    }
  }
  std::printf("Fresnel extracted from a Cook-Torrance/GGX material (theta_d <= 70): max relative error %.2e\n", worst);
  EXPECT_LT(worst, 2e-3);  // the G1 table interpolation
}

TEST(FresnelExtraction, RefusesModelsWithoutMicrofacetDistribution) {
  const FunctionBrdf data = material(ggx_values(0.2));
  const Model& lambert = model_by_name("lambert");
  EXPECT_THROW(analysis::extract_fresnel(data, lambert, ParamValues::defaults(lambert.params())), InputError);
}

TEST(Diffraction, SeparatesFunctionsOfFFromFunctionsOfThetaH) {
  // ρ = kd/π + 1/(1 + f²/a²)² (seed 004 Eq. 13's Sz) with f = (2/λ) sinθh cosθd, and ρ = D_GGX(θh).
  const FunctionBrdf diffraction([](const Vec3d& wi, const Vec3d& wo) {
    const HalfDiff hd = to_half_diff(wi, wo);
    Rgb r;
    for (int c = 0; c < 3; ++c) {
      const double f = 2 / kChannelWavelengthUm[c] * std::sin(hd.theta_h) * std::cos(hd.theta_d);
      const double s = 1 + f * f / (0.9 * 0.9);
      r[c] = 0.05 + 1 / (s * s);
    }
    return r;
  });
  const double alpha = 0.3;
  const Ggx<double> ggx(&alpha);
  const FunctionBrdf specular([&ggx](const Vec3d& wi, const Vec3d& wo) {
    const double d = ggx.D((wi + wo).normalized().z());
    return Rgb(d, d, d);
  });
  analysis::DiffractionOptions opt;
  opt.theta_h_cells = opt.theta_d_cells = 45;
  opt.phi_d_samples = 8;
  const auto a = analysis::diffraction_map(diffraction, opt);
  const auto b = analysis::diffraction_map(specular, opt);
  std::printf("diffraction-dominated fraction: Sz(f) material R %.3f G %.3f B %.3f; D(theta_h) material R %.3f\n",
              a.diffraction_fraction[0], a.diffraction_fraction[1], a.diffraction_fraction[2], b.diffraction_fraction[0]);
  for (int c = 0; c < 3; ++c) EXPECT_GT(a.diffraction_fraction[size_t(c)], 0.8);  // measured 0.948 0.903 0.842
  EXPECT_LT(b.diffraction_fraction[0], 0.3);
  // Variance over φd is zero for functions of (θh, θd) only.
  for (const auto& cell : a.cells) EXPECT_LT(cell.variance.maxCoeff(), 1e-20 + 1e-12 * cell.mean.maxCoeff());
}

TEST(Backscatter, RecoversTheFamilyAndWidthOfASyntheticSlice) {
  const ParamValues v = ggx_values(0.15);
  const FunctionBrdf data = material(v);
  analysis::BackscatterOptions opt;
  opt.families = {"beckmann", "ggx", "sgd"};
  const auto a = analysis::analyze_backscatter(data, opt);
  const auto& ggx = a.fits[1];
  std::printf("synthetic GGX alpha 0.15 slice: GGX fit alpha %.5f %.5f %.5f, err %.2e; Beckmann err %.2e; SGD err %.2e\n",
              ggx.shape[0][0], ggx.shape[1][0], ggx.shape[2][0], ggx.mean_error_linear, a.fits[0].mean_error_linear,
              a.fits[2].mean_error_linear);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(ggx.shape[size_t(c)][0], 0.15, 1e-4);
    // ρd = kd and Fr = ρs F(0) = (π/4) ks F0 (models/cook_torrance.h's ks = 4 ρs/π).
    EXPECT_NEAR(ggx.rho_d[size_t(c)], 0.1, 1e-4);
    EXPECT_NEAR(ggx.fr[size_t(c)], kPi / 4 * 0.8 * v.values[size_t(c)][3], 1e-4);
  }
  EXPECT_LT(ggx.mean_error_linear, 1e-5);
  EXPECT_GT(a.fits[0].mean_error_linear, 10 * ggx.mean_error_linear);
}

TEST(AlbedoCurve, DataAndModelAgreeForTheSameFunction) {
  const ParamValues v = ggx_values(0.3);
  const FunctionBrdf data = material(v);
  const auto curve = analysis::albedo_curve(data, &ggx_model(), &v, {0, 80, 20});
  ASSERT_EQ(curve.theta_i_deg.size(), 5u);
  for (size_t k = 0; k < curve.theta_i_deg.size(); ++k) {
    ASSERT_TRUE(curve.data[k] && curve.model[k]);
    EXPECT_LT(((*curve.data[k]) - (*curve.model[k])).abs().maxCoeff(), 1e-12);
    EXPECT_GT((*curve.data[k]).minCoeff(), 0.1);  // kd = 0.1 alone gives 0.1
  }
}

TEST(AnalyzeCli, BadInputGivesExitCode2) {
  auto r = test::run_cli("analyze /nonexistent.binary --what backscatter");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  BRDFKIT_REQUIRE_DATA("cornell");
  const auto cornell = (test::data_dir() / "cornell" / "acryl_blue.brdf").string();
  r = test::run_cli("analyze " + cornell + " --what bogus");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--what"), std::string::npos) << r.err;
  r = test::run_cli("analyze " + cornell + " --what backscatter");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("back-scattering"), std::string::npos) << r.err;
}

TEST(AnalyzeCli, BackscatterOnPinkFeltWritesJsonAndCsv) {
  BRDFKIT_REQUIRE_DATA("merl-slices");
  const auto dir = test::scratch_dir("analyze_cli");
  const auto file = (test::data_dir() / "merl-slices" / "pink-felt-1d.alta").string();
  auto r = test::run_cli("analyze " + file + " --what backscatter --families ggx,sgd -o " + (dir / "b.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("sgd"), std::string::npos);
  const auto j = nlohmann::json::parse(std::ifstream(dir / "b.json"));
  EXPECT_EQ(j["fits"].size(), 2u);
  EXPECT_GT(j["slice"].size(), 50u);
  r = test::run_cli("analyze " + file + " --what backscatter --families ggx --csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("theta_h_deg,m_r,m_g,m_b,ggx_model_r", 0), 0u) << r.out.substr(0, 200);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace brdfkit
