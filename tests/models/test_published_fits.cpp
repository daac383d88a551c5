// Published fits (data/published-fits, DESIGN.md §10): each file loads into its brdfkit model
// with the meaning of the file's `conventions` (checked against the conventions' formulas
// written out here), and fits of different papers for one material agree in albedo.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "brdfkit/core/error.h"
#include "brdfkit/models/published_fits.h"
#include "support/mc_albedo.h"
#include "support/test_util.h"

namespace brdfkit {
namespace {

std::filesystem::path fits_dir() { return test::data_dir() / "published-fits"; }

nlohmann::json lobe_params(const std::string& file, const std::string& material, const std::string& lobe) {
  std::ifstream in(fits_dir() / file);
  const auto doc = nlohmann::json::parse(in);
  for (const auto& l : doc["materials"][material])
    if (l["lobe"] == lobe) return l["params"];
  return {};
}

// Cook-Torrance dielectric F as the files' conventions print it.
double ct_fresnel(double c, double eta) {
  const double g = std::sqrt(eta * eta + c * c - 1);
  const double a = (g - c) / (g + c), b = (c * (g + c) - 1) / (c * (g - c) + 1);
  return 0.5 * a * a * (1 + b * b);
}

struct Pair {
  Vec3d wi, wo;
};
std::vector<Pair> pairs() {
  return {{spherical_direction(0.3, 0.0), spherical_direction(0.32, kPi + 0.01)},
          {spherical_direction(0.7, 0.2), spherical_direction(0.75, kPi + 0.25)},
          {spherical_direction(1.0, 0.0), spherical_direction(0.4, 2.0)},
          {spherical_direction(0.1, 1.0), spherical_direction(1.2, 1.5)}};
}

// Each supported file against its `conventions` formula, evaluated here from the JSON.
TEST(PublishedFits, MatchConventionsFormulas) {
  BRDFKIT_REQUIRE_DATA("published-fits");
  for (const std::string mat : {"alum-bronze", "red-plastic", "gold-metallic-paint"}) {
    {  // rho = albedo/π + A (1 + B |Dp|²)^−C F(sqrt(1 − |Lp − Vp|²/4))
      const auto fits = PublishedFits::read(fits_dir() / "low2012-smooth-E2.json");
      const Brdf b = fits.brdf(mat);
      const auto kd = lobe_params("low2012-smooth-E2.json", mat, "Lambertian")["albedo"];
      const auto p = lobe_params("low2012-smooth-E2.json", mat, "LowSmooth");
      for (const auto& [wi, wo] : pairs()) {
        const double dp2 = std::pow(wi.x() + wo.x(), 2) + std::pow(wi.y() + wo.y(), 2);
        const double lv2 = std::pow(wi.x() - wo.x(), 2) + std::pow(wi.y() - wo.y(), 2);
        const Rgb got = b.eval(wi, wo);
        for (int c = 0; c < 3; ++c) {
          const double want = kd[c].get<double>() / kPi + p["A"][c].get<double>() *
                                                              std::pow(1 + p["B"].get<double>() * dp2, -p["C"].get<double>()) *
                                                              ct_fresnel(std::sqrt(1 - lv2 / 4), p["eta"].get<double>());
          EXPECT_NEAR(got[c], want, 1e-12 * want) << mat << " smooth c" << c;
        }
      }
    }
    {  // rho = albedo/π + ks (n+1)/(8π) cosⁿθh F(wi·h) / ((wi·h) max(ci, co))
      const auto fits = PublishedFits::read(fits_dir() / "low2012-ashikhminshirley-E2.json");
      const Brdf b = fits.brdf(mat);
      const auto kd = lobe_params("low2012-ashikhminshirley-E2.json", mat, "Lambertian")["albedo"];
      const auto p = lobe_params("low2012-ashikhminshirley-E2.json", mat, "LowAshikhminShirley");
      for (const auto& [wi, wo] : pairs()) {
        const Vec3d h = (wi + wo).normalized();
        const double n = p["sharpness"].get<double>();
        const Rgb got = b.eval(wi, wo);
        for (int c = 0; c < 3; ++c) {
          const double want = kd[c].get<double>() / kPi +
                              p["albedo"][c].get<double>() * (n + 1) / (8 * kPi) * std::pow(h.z(), n) *
                                  ct_fresnel(wi.dot(h), p["fresnelReflectance"].get<double>()) /
                                  (wi.dot(h) * std::max(wi.z(), wo.z()));
          EXPECT_NEAR(got[c], want, 1e-12 * want) << mat << " AS c" << c;
        }
      }
    }
    {  // rho = albedo/π + ks exp(−tan²θh/m²)/(m² cos⁴θh) G F / (π ci co), V-groove G
      const auto fits = PublishedFits::read(fits_dir() / "low2012-cooktorrance-E1.json");
      const Brdf b = fits.brdf(mat);
      const auto kd = lobe_params("low2012-cooktorrance-E1.json", mat, "Lambertian")["albedo"];
      const auto p = lobe_params("low2012-cooktorrance-E1.json", mat, "LowCookTorrance");
      for (const auto& [wi, wo] : pairs()) {
        const Vec3d h = (wi + wo).normalized();
        const double m = p["roughness"].get<double>(), ch = h.z();
        const double tan2 = (1 - ch * ch) / (ch * ch);
        const double d = std::exp(-tan2 / (m * m)) / (m * m * std::pow(ch, 4));
        const double g = std::min({1.0, 2 * ch * wo.z() / wo.dot(h), 2 * ch * wi.z() / wo.dot(h)});
        const double f = ct_fresnel(wi.dot(h), p["eta"].get<double>());
        const Rgb got = b.eval(wi, wo);
        for (int c = 0; c < 3; ++c) {
          const double want = kd[c].get<double>() / kPi + p["albedo"][c].get<double>() * d * g * f / (kPi * wi.z() * wo.z());
          EXPECT_NEAR(got[c], want, 1e-12 * want) << mat << " CT c" << c;
        }
      }
    }
    {  // rho = albedo/π + A (1 + B(1 − cosθh))^−C G F / (π ci co), V-groove G
      const auto fits = PublishedFits::read(fits_dir() / "low2012-microfacet-E2.json");
      ASSERT_TRUE(fits.supported()) << fits.unsupported_reason();
      const Brdf b = fits.brdf(mat);
      const auto kd = lobe_params("low2012-microfacet-E2.json", mat, "Lambertian")["albedo"];
      const auto p = lobe_params("low2012-microfacet-E2.json", mat, "LowMicrofacetFit");
      for (const auto& [wi, wo] : pairs()) {
        const Vec3d h = (wi + wo).normalized();
        const double ch = h.z();
        const double s = std::pow(1 + p["B"].get<double>() * (1 - ch), -p["C"].get<double>());
        const double g = std::min({1.0, 2 * ch * wo.z() / wo.dot(h), 2 * ch * wi.z() / wo.dot(h)});
        const double f = ct_fresnel(wi.dot(h), p["eta"].get<double>());
        const Rgb got = b.eval(wi, wo);
        for (int c = 0; c < 3; ++c) {
          const double want = kd[c].get<double>() / kPi + p["A"][c].get<double>() * s * g * f / (kPi * wi.z() * wo.z());
          EXPECT_NEAR(got[c], want, 1e-12 * want) << mat << " microfacet c" << c;
        }
      }
    }
  }
}

// Bagher 2012: rho = albedo/π + albedo K e^{−t} t^{−p}/(π cos⁴θh) G F/(π ci co), t = α + tan²θh/α,
// F = F0 + (1 − F0)(1 − cos θd)⁵ − F1 cos θd. brdfkit's G is Smith from the SGD Λ, not the file's
// fitted Eq. 9 approximation, so compare near normal incidence where both G are ≈ 1 (2 %).
TEST(PublishedFits, BagherMatchesConventionsNearNormal) {
  BRDFKIT_REQUIRE_DATA("published-fits");
  const auto fits = PublishedFits::read(fits_dir() / "bagher2012-sgd.json");
  ASSERT_TRUE(fits.supported()) << fits.unsupported_reason();
  for (const std::string mat : {"alum-bronze", "white-fabric2"}) {
    const Brdf b = fits.brdf(mat);
    const auto kd = lobe_params("bagher2012-sgd.json", mat, "Lambertian")["albedo"];
    const auto p = lobe_params("bagher2012-sgd.json", mat, "Bagher");
    const Pair near[] = {{spherical_direction(0.2, 0.0), spherical_direction(0.2, kPi + 0.002)},
                         {spherical_direction(0.1, 0.3), spherical_direction(0.3, kPi + 0.3)}};
    for (const auto& [wi, wo] : near) {
      const Vec3d h = (wi + wo).normalized();
      const double ch = h.z(), tan2 = (1 - ch * ch) / (ch * ch), cd = wi.dot(h);
      const Rgb got = b.eval(wi, wo);
      for (int c = 0; c < 3; ++c) {
        const double al = p["alpha"][c].get<double>(), pp = p["p"][c].get<double>();
        const double t = al + tan2 / al;
        const double d = p["K"][c].get<double>() * std::exp(-t) / std::pow(t, pp) / (kPi * std::pow(ch, 4));
        const double f0 = p["eta"][0][c].get<double>(), f1 = p["eta"][1][c].get<double>();
        const double f = f0 + (1 - f0) * std::pow(1 - cd, 5) - f1 * cd;
        const double spec = p["albedo"][c].get<double>() * d * f / (kPi * wi.z() * wo.z());
        const double want = kd[c].get<double>() / kPi + spec;
        EXPECT_NEAR(got[c], want, 0.02 * std::abs(spec) + 1e-12) << mat << " Bagher c" << c;
      }
    }
  }
}

TEST(PublishedFits, UnsupportedAndBadInputAreClearErrors) {
  BRDFKIT_REQUIRE_DATA("published-fits");
  const auto micro = PublishedFits::read(fits_dir() / "low2012-microfacet-E2.json");
  EXPECT_TRUE(micro.supported()) << micro.unsupported_reason();
  EXPECT_EQ(micro.model_name(), "low-microfacet");
  EXPECT_EQ(micro.materials().size(), 100u);
  const auto smooth = PublishedFits::read(fits_dir() / "low2012-smooth-E2.json");
  EXPECT_THROW(smooth.brdf("no-such-material"), InputError);

  const auto dir = test::scratch_dir("published_fits");
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  };
  const auto unknown = PublishedFits::read(write(
      "unknown.json", R"({"materials": {"m": [{"lobe": "Lambertian", "params": {"albedo": [0.1, 0.1, 0.1]}},
                                             {"lobe": "MysteryLobe", "params": {"x": 1}}]}})"));
  EXPECT_FALSE(unknown.supported());
  try {
    unknown.brdf("m");
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("MysteryLobe"), std::string::npos) << e.what();
  }
  EXPECT_THROW(PublishedFits::read(dir / "absent.json"), InputError);
  EXPECT_THROW(PublishedFits::read(write("bad.json", "{not json")), InputError);
  EXPECT_THROW(PublishedFits::read(write("empty.json", "{\"materials\": {}}")), InputError);
  const auto missing = PublishedFits::read(write(
      "missing.json",
      R"({"materials": {"m": [{"lobe": "Lambertian", "params": {"albedo": [0.1, 0.1, 0.1]}},
                               {"lobe": "LowSmooth", "params": {"A": [1, 1, 1], "B": 10, "eta": 1.5}}]}})"));
  try {
    missing.brdf("m");
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'C'"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

// The files' diffuse albedo is the directional albedo of the model with its specular lobe off,
// at any angle (Lambert: a = kd exactly; a factor π in the "albedo/π" convention would show).
TEST(PublishedFits, DiffuseAlbedoIsTheFilesLambertianAlbedo) {
  BRDFKIT_REQUIRE_DATA("published-fits");
  int checked = 0;
  for (const auto& path : published_fit_files(fits_dir())) {
    const auto fits = PublishedFits::read(path);
    ASSERT_TRUE(fits.supported()) << fits.stem() << ": " << fits.unsupported_reason();
    for (const std::string mat : {"alum-bronze", "steel", "pink-felt", "white-acrylic"}) {
      const Brdf b = fits.brdf(mat);
      const ParamTable& t = b.model().params();
      ParamValues diffuse = b.values();
      for (size_t i = 0; i < t.size(); ++i)
        if (t[i].linear && t[i].name != "kd")
          for (auto& ch : diffuse.values) ch[i] = 0.0;
      const auto kd = lobe_params(path.filename().string(), mat, "Lambertian")["albedo"];
      for (int c = 0; c < 3; ++c)
        for (double deg : {0.0, 60.0}) {
          const double a = test::mc_albedo(b.model(), diffuse.channel(c), c, deg * kPi / 180, 8);
          EXPECT_NEAR(a, kd[c].get<double>(), 1e-12) << fits.stem() << " " << mat << " channel " << c << " at " << deg;
        }
      ++checked;
    }
  }
  EXPECT_EQ(checked, 7 * 4);
}

// Löw's Ashikhmin-Shirley lobe (n+1)/(8π) cosⁿθh F/((wi·h) max(ci, co)) integrates to ks F(cosθ)
// as n grows (with dωi = 4 (wo·h) dωh the lobe becomes F (n+1)/(2π) cosⁿθh dωh near the mirror
// direction, where ci = co): so a(30°) = kd + ks F(cos 30°; fresnelReflectance) for the sharp
// fits (sharpness ≥ 1000, every material of both files), to O(1/n) and the Monte Carlo noise.
TEST(PublishedFits, AshikhminShirleyAlbedoIsKdPlusKsFInTheSharpLimit) {
  BRDFKIT_REQUIRE_DATA("published-fits");
  const double cos30 = std::cos(30 * kPi / 180);
  for (const std::string file : {"low2012-ashikhminshirley-E1.json", "low2012-ashikhminshirley-E2.json"}) {
    const auto fits = PublishedFits::read(fits_dir() / file);
    double worst = 0;
    int sharp = 0;
    for (const auto& mat : fits.materials()) {
      const auto p = lobe_params(file, mat, "LowAshikhminShirley");
      if (p["sharpness"].get<double>() < 1000) continue;
      ++sharp;
      const auto kd = lobe_params(file, mat, "Lambertian")["albedo"];
      const Brdf b = fits.brdf(mat);
      for (int c = 0; c < 3; ++c) {
        const double want =
            kd[c].get<double>() + p["albedo"][c].get<double>() * ct_fresnel(cos30, p["fresnelReflectance"].get<double>());
        const double got = test::mc_albedo(b.model(), b.values().channel(c), c, 30 * kPi / 180, 32);
        worst = std::max(worst, std::abs(got - want) / want);
        EXPECT_NEAR(got, want, 0.02 * want) << file << " " << mat << " channel " << c;
      }
    }
    std::printf("%s: %d sharp fits, a(30 deg) vs kd + ks F(cos 30 deg): worst relative difference %.3g\n", file.c_str(),
                sharp, worst);
    EXPECT_GT(sharp, 20);
  }
}

// Directional albedo at θi = 30° (luminance) of every material in every loadable file: the
// fits describe the same 100 measurements, so they agree (a convention's factor π or 4 would
// show at once). Median ≤ 1.2 as DESIGN.md §10's independent check found (median 1.10). Its
// worst case (2.03) is exceeded by one pair of Löw's own fits: steel, Ashikhmin-Shirley E1
// (ks·F ≈ 0.105·0.65 + kd 0.066 → Y 0.134) against E2 (0.613·0.070 + 0.018 → Y 0.062), ratio
// 2.17 by hand from the files' conventions as well; so the per-material bound here is 2.2.
TEST(PublishedFits, AlbedosAgreeAcrossFiles) {
  BRDFKIT_REQUIRE_DATA("published-fits");
  std::map<std::string, std::vector<std::pair<std::string, double>>> by_material;
  int loaded = 0;
  for (const auto& path : published_fit_files(fits_dir())) {
    const auto fits = PublishedFits::read(path);
    if (!fits.supported()) {
      std::cout << "[ skipped  ] " << fits.stem() << ": " << fits.unsupported_reason() << "\n";
      continue;
    }
    ++loaded;
    EXPECT_EQ(fits.materials().size(), 100u) << fits.stem();
    for (const auto& mat : fits.materials()) {
      const Brdf b = fits.brdf(mat);
      double a[3];
      for (int c = 0; c < 3; ++c)
        a[c] = test::mc_albedo(b.model(), b.values().channel(c), c, 30.0 * kPi / 180, 32);
      const double y = test::luminance(a[0], a[1], a[2]);
      ASSERT_TRUE(std::isfinite(y) && y > 0) << fits.stem() << " " << mat;
      by_material[mat].push_back({fits.stem(), y});
    }
  }
  ASSERT_GE(loaded, 7);  // every file of the folder, Löw's microfacet fits included
  std::vector<double> ratios;
  for (const auto& [mat, list] : by_material) {
    double lo = 1e300, hi = 0;
    std::string lo_f, hi_f;
    for (const auto& [f, y] : list) {
      if (y < lo) lo = y, lo_f = f;
      if (y > hi) hi = y, hi_f = f;
    }
    const double r = hi / lo;
    ratios.push_back(r);
    EXPECT_LE(r, 2.2) << mat;
    if (r > 1.5)
      std::cout << "[ ratio>1.5] " << mat << " " << r << " (max " << hi << " " << hi_f << ", min " << lo << " " << lo_f
                << ")\n";
  }
  std::sort(ratios.begin(), ratios.end());
  const double median = ratios[ratios.size() / 2];
  std::cout << "[ albedo   ] files " << loaded << ", materials " << ratios.size() << ", median max/min " << median
            << ", worst " << ratios.back() << "\n";
  EXPECT_LE(median, 1.2);
}

}  // namespace
}  // namespace brdfkit
