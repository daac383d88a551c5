// Observations on synthetic materials whose answer is known: Fresnel extraction (seed 000 Eq. 10)
// returns the Schlick curve a Cook-Torrance material was made with; the diffraction test (seed 004
// §4.2) classifies a pure function of f as diffraction-dominated and a pure function of θh mostly
// not; the back-scattering fit (seed 000 Eq. 7, 12) recovers the family and parameter of its data.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "brdfkit/analysis/albedo_curve.h"
#include "brdfkit/analysis/backscatter.h"
#include "brdfkit/measured/diffraction_map.h"
#include "brdfkit/analysis/fresnel_extraction.h"
#include "brdfkit/core/error.h"
#include "brdfkit/core/half_diff.h"
#include "brdfkit/models/model.h"
#include "brdfkit/ndf/ggx.h"
#include "support/output_lines.h"
#include "support/test_util.h"

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
  DiffractionOptions opt;
  opt.theta_h_cells = opt.theta_d_cells = 45;
  opt.phi_d_samples = 8;
  const auto a = diffraction_map(diffraction, opt);
  const auto b = diffraction_map(specular, opt);
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
  EXPECT_EQ(r.err, "brdfkit: --what: 'bogus' is not one of backscatter, fresnel, diffraction, albedo, ndf\n");
  r = test::run_cli("analyze " + cornell + " --what backscatter");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(test::lines_of(r.err).size(), 1u) << r.err;
  EXPECT_TRUE(test::line_starting(r.err, "brdfkit: " + cornell + ": fewer than 4 values on the back-scattering slice"))
      << r.err;
}

TEST(AnalyzeCli, BackscatterOnPinkFeltWritesJsonAndCsv) {
  BRDFKIT_REQUIRE_DATA("merl-slices");
  const auto dir = test::scratch_dir("analyze_cli");
  const auto file = (test::data_dir() / "merl-slices" / "pink-felt-1d.alta").string();
  auto r = test::run_cli("analyze " + file + " --what backscatter --families beckmann,ggx -o " + (dir / "b.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(std::ifstream(dir / "b.json"));
  ASSERT_EQ(j["fits"].size(), 2u);
  // One table row per family, led by its name, with the errors the JSON holds (5 decimals on
  // screen; cheap families: the fits themselves are tested in test_real_data).
  for (const auto& f : j["fits"]) {
    const auto row = test::line_led_by(r.out, f["family"].get<std::string>());
    ASSERT_TRUE(row) << f["family"] << "\n" << r.out;
    const auto t = test::tokens_of(*row);
    ASSERT_GE(t.size(), 3u) << *row;
    EXPECT_NEAR(std::stod(t[1]), f["mean_error_linear"].get<double>(), 5e-6) << *row;
    EXPECT_NEAR(std::stod(t[2]), f["mean_error_log"].get<double>(), 5e-6) << *row;
  }
  EXPECT_GT(j["slice"].size(), 50u);
  r = test::run_cli("analyze " + file + " --what backscatter --families ggx --csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("theta_h_deg,m_r,m_g,m_b,ggx_model_r", 0), 0u) << r.out.substr(0, 200);
  std::filesystem::remove_all(dir);
}

// Every number in a document is finite (nlohmann writes NaN and ±inf as null, so the nulls that
// are allowed are named by the caller's checks, not here).
int count_numbers(const nlohmann::json& j) {
  if (j.is_number()) {
    EXPECT_TRUE(std::isfinite(j.get<double>()));
    return 1;
  }
  int n = 0;
  if (j.is_array() || j.is_object())
    for (const auto& v : j) n += count_numbers(v);
  return n;
}

bool all_rgb_numbers(const nlohmann::json& v) {
  return v.is_array() && v.size() == 3 && v[0].is_number() && v[1].is_number() && v[2].is_number();
}

// fresnel, diffraction, albedo end to end on a real RGL file, at coarse grids (the numbers are
// checked by the library tests above; here: the JSON parses, has its fields, and is finite).
TEST(AnalyzeCli, FresnelDiffractionAlbedoWriteFiniteJson) {
  BRDFKIT_REQUIRE_DATA("rgl");
  const auto file = (test::data_dir() / "rgl" / "paper_white_rgb.bsdf").string();
  auto r = test::run_cli("analyze " + file + " --what fresnel --coarsen 4 --starts 1 --nodes 16 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;  // no solver noise on stderr
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["analysis"], "fresnel");
  EXPECT_EQ(j["model"], "cook-torrance-ggx");
  ASSERT_EQ(j["rows"].size(), 16u);
  for (const auto& row : j["rows"]) {
    EXPECT_TRUE(row["theta_d"].is_number());
    EXPECT_TRUE(all_rgb_numbers(row["model"])) << row.dump();
  }
  EXPECT_GT(count_numbers(j), 100);

  r = test::run_cli("analyze " + file + " --what diffraction --nodes 8 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["analysis"], "diffraction");
  ASSERT_EQ(j["summary"].size(), 3u);
  for (const auto& ch : j["summary"]) {
    EXPECT_GT(ch["classified"].get<int>(), 0);
    EXPECT_GE(ch["fraction"].get<double>(), 0.0);
    EXPECT_LE(ch["fraction"].get<double>(), 1.0);
  }
  ASSERT_FALSE(j["cells"].empty());
  int filled = 0;
  for (const auto& c : j["cells"]) {
    EXPECT_GE(c["count"].get<int>(), 0);
    if (c["count"].get<int>() == 0) continue;  // cells beyond the horizon have no sample
    ++filled;
    EXPECT_TRUE(all_rgb_numbers(c["mean"]) && all_rgb_numbers(c["variance"])) << c.dump();
  }
  EXPECT_GT(filled, 0);
  count_numbers(j);

  r = test::run_cli("analyze " + file + " --what albedo --nodes 8 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["analysis"], "albedo");
  ASSERT_GE(j["rows"].size(), 8u);
  for (const auto& row : j["rows"]) {
    ASSERT_TRUE(all_rgb_numbers(row["data"])) << row.dump();
    for (int c = 0; c < 3; ++c) {
      EXPECT_GT(row["data"][c].get<double>(), 0.0);
      EXPECT_LT(row["data"][c].get<double>(), 1.2);  // paper_white: albedo ≈ 0.8–1, energy conserving within noise
    }
  }
  count_numbers(j);
}

// `--what ndf -o t.json` then `--what ndf --params t.json`: the reloaded table and parameters score
// the same error on the same grid as when they were estimated.
TEST(AnalyzeCli, NdfEstimateReloadsFromItsJson) {
  BRDFKIT_REQUIRE_DATA("rgl");
  const auto dir = test::scratch_dir("analyze_ndf_cli");
  const auto file = (test::data_dir() / "rgl" / "paper_white_rgb.bsdf").string();
  const auto saved = (dir / "t.json").string();
  auto r = test::run_cli("analyze " + file + " --what ndf --coarsen 4 --nodes 24 --f0 0.05 -o " + saved);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto first = nlohmann::json::parse(std::ifstream(saved));
  ASSERT_TRUE(first.contains("ndf_table") && first.contains("parameters") && first.contains("metrics"));
  EXPECT_EQ(first["ndf_table"]["theta"].size(), 24u);
  count_numbers(first);
  r = test::run_cli("analyze " + file + " --what ndf --coarsen 4 --params " + saved + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto again = nlohmann::json::parse(r.out);
  EXPECT_EQ(again["parameters"], first["parameters"]);
  const double e0 = first["metrics"]["ngan"].get<double>(), e1 = again["metrics"]["ngan"].get<double>();
  std::printf("ndf estimate ngan %.9f, reloaded %.9f\n", e0, e1);
  EXPECT_NEAR(e1, e0, 1e-9 * e0);
  r = test::run_cli("analyze " + file + " --what ndf --params " + (dir / "missing.json").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace brdfkit
