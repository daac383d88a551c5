// Ngan 2005's published fits (seed 002; data/published-fits/ngan2005, BBM's text form): the
// Ashikhmin-Shirley lobe in seed 002's form against an independent transcription, every parameter
// set loads and evaluates, and the conventions (models/bbm_fit_text.cpp) hold in numbers: the
// albedo at θi = 30° agrees with Bagher's and Löw's fits of the same materials.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <string>

#include "brdfkit/core/error.h"
#include "brdfkit/models/bbm_fit_text.h"
#include "brdfkit/models/published_fits.h"
#include "support/mc_albedo.h"
#include "support/test_util.h"

namespace brdfkit {
namespace {

std::filesystem::path fits_dir() { return test::data_dir() / "published-fits"; }
std::filesystem::path ngan_dir() { return fits_dir() / "ngan2005"; }

const char* const kNganFiles[] = {"ngan_ashikhminshirley.fit", "ngan_blinnphong.fit", "ngan_cooktorrance.fit",
                                  "ngan_he.fit",               "ngan_lafortune.fit",  "ngan_ward.fit",
                                  "ngan_wardduer.fit"};
const double kMerlScale[3] = {1.0, 1.15, 1.66};  // DESIGN.md §2

std::vector<std::pair<Vec3d, Vec3d>> pairs() {
  return {{spherical_direction(0.3, 0.0), spherical_direction(0.32, kPi + 0.01)},
          {spherical_direction(0.7, 0.2), spherical_direction(0.75, kPi + 0.25)},
          {spherical_direction(1.0, 0.0), spherical_direction(0.4, 2.0)},
          {spherical_direction(0.1, 1.0), spherical_direction(1.2, 1.5)},
          {spherical_direction(1.5, 0.0), spherical_direction(1.55, kPi)}};
}

// ρ = kd/π + ρs · Schlick(F0; wi·h) · (n+1)/(8π) cosⁿθh / ((wi·h) max(cosθi, cosθo)), written
// out from published-fits/ngan2005/README.md, with the file's values times MERL's factors.
TEST(NganPublishedFits, AshikhminShirleyIsSeed002Form) {
  BRDFKIT_REQUIRE_DATA("published-fits/ngan2005");
  const auto fits = PublishedFits::read(ngan_dir() / "ngan_ashikhminshirley.fit");
  EXPECT_EQ(fits.model_name(), "ashikhmin-shirley-ngan2005");
  const nlohmann::json doc = read_bbm_fit_text(ngan_dir() / "ngan_ashikhminshirley.fit");
  for (const std::string mat : {"blue-acrylic", "gold-metallic-paint", "steel", "pink-felt"}) {
    const Brdf b = fits.brdf(mat);
    const auto& kd = doc["materials"][mat][0]["params"]["albedo"];
    const auto& p = doc["materials"][mat][1]["params"];
    const double f0 = p["fresnelReflectance"].get<double>(), n = p["sharpness"].get<double>();
    for (const auto& [wi, wo] : pairs()) {
      const Vec3d h = (wi + wo).normalized();
      const double c = wi.dot(h);
      const double schlick = f0 + (1 - f0) * std::pow(1 - c, 5);
      const double lobe = (n + 1) / (8 * kPi) * std::pow(h.z(), n) / (c * std::max(wi.z(), wo.z()));
      const Rgb got = b.eval(wi, wo);
      for (int ch = 0; ch < 3; ++ch) {
        const double want = kMerlScale[ch] * (kd[ch].get<double>() / kPi + p["albedo"][ch].get<double>() * schlick * lobe);
        EXPECT_NEAR(got[ch], want, 1e-12 * want) << mat << " channel " << ch;
      }
    }
  }
}

TEST(NganPublishedFits, EveryParameterSetLoadsAndEvaluates) {
  BRDFKIT_REQUIRE_DATA("published-fits/ngan2005");
  for (const char* file : kNganFiles) {
    const auto fits = PublishedFits::read(ngan_dir() / file);
    ASSERT_TRUE(fits.supported()) << file << ": " << fits.unsupported_reason();
    EXPECT_EQ(fits.materials().size(), 86u) << file;
    for (const auto& mat : fits.materials()) {
      const Brdf b = fits.brdf(mat);
      for (const auto& [wi, wo] : pairs()) {
        const Rgb v = b.eval(wi, wo);
        EXPECT_TRUE(v.allFinite() && (v.array() >= 0).all()) << file << " " << mat;
      }
    }
  }
}

TEST(NganPublishedFits, TextErrorsNameFileAndLine) {
  const auto dir = test::scratch_dir("ngan_text");
  const auto write = [&](const std::string& text) {
    std::ofstream(dir / "bad.fit") << text;
    return dir / "bad.fit";
  };
  const auto message = [&](const std::string& text) {
    try {
      read_bbm_fit_text(write(text));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("# c\nx = Aggregate(Lambertian(albedo = [1, 2, 3]), NganWard(albedo = [1, 2, 3], roughness = nan))\n")
                .find("bad.fit:2: expected a finite number"),
            std::string::npos);
  EXPECT_NE(message("x = Aggregate(Lambertian(albedo = [1, 2, 3])\n").find("bad.fit:1: expected ')'"), std::string::npos);
  EXPECT_NE(message("x = Aggregate(Lambertian(albedo = 1))\nx = Aggregate(Lambertian(albedo = 1))\n")
                .find("'x' appears twice"),
            std::string::npos);
  EXPECT_NE(message("# only a comment\n").find("no material line"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// The albedo at θi = 30° per channel, by the model's own sampler.
Rgb albedo(const Brdf& b) {
  Rgb a;
  for (int c = 0; c < 3; ++c) a[c] = test::mc_albedo(b.model(), b.values().channel(c), c, 30.0 * kPi / 180, 32);
  return a;
}
double luminance(const Rgb& a) { return test::luminance(a[0], a[1], a[2]); }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
double spread(const std::vector<double>& v) {
  return *std::max_element(v.begin(), v.end()) / *std::min_element(v.begin(), v.end());
}

struct Others {
  std::map<std::string, std::vector<double>> y;  // material → luminance of Bagher's and Löw's fits
  std::map<std::string, Rgb> bagher;             // material → Bagher's albedo per channel
};
const Others& others() {
  static const Others o = [] {
    Others o;
    for (const auto& path : published_fit_files(fits_dir())) {
      const auto fits = PublishedFits::read(path);
      if (!fits.supported()) continue;
      for (const auto& mat : fits.materials()) {
        const Rgb a = albedo(fits.brdf(mat));
        o.y[mat].push_back(luminance(a));
        if (fits.model_name() == "cook-torrance-sgd-bagher2012") o.bagher[mat] = a;
      }
    }
    return o;
  }();
  return o;
}

// Per Ngan model, max/min of the albedo over that model's fit and Bagher's and Löw's fits of the
// material: median ≤ 1.2, the bound Bagher's and Löw's fits meet among themselves
// (test_published_fits.cpp). Materials where Ngan's fit lies outside the others' range by more
// than 1.5× are printed.
TEST(NganPublishedFits, AlbedosAgreeWithBagherAndLow) {
  BRDFKIT_REQUIRE_DATA("published-fits/ngan2005");
  std::vector<double> among_others;
  for (const auto& [mat, ys] : others().y) among_others.push_back(spread(ys));
  ASSERT_GE(others().y.begin()->second.size(), 7u);
  std::cout << "[ albedo   ] Bagher and Low among themselves: median max/min " << median(among_others) << "\n";
  for (const char* file : kNganFiles) {
    const auto fits = PublishedFits::read(ngan_dir() / file);
    std::vector<double> ratios;
    for (const auto& mat : fits.materials()) {
      std::vector<double> ys = others().y.at(mat);
      const double lo = *std::min_element(ys.begin(), ys.end()), hi = *std::max_element(ys.begin(), ys.end());
      const double y = luminance(albedo(fits.brdf(mat)));
      ys.push_back(y);
      ratios.push_back(spread(ys));
      if (y > 1.5 * hi || y < lo / 1.5)
        std::cout << "[ outlier  ] " << file << " " << mat << ": " << y << " against [" << lo << ", " << hi << "]\n";
    }
    std::cout << "[ albedo   ] " << file << ": median max/min " << median(ratios) << "\n";
    EXPECT_LE(median(ratios), 1.2) << file;
  }
}

// The conventions' factors, each seen in the albedos. MERL's channel factors: Ngan's albedo over
// Bagher's per channel, medians over every model and material, is 1 in each channel once the
// factors are applied (the files' raw values give 1 : 1/1.15 : 1/1.66). The lobes' factors: below.
TEST(NganPublishedFits, ConventionFactorsShowInTheAlbedo) {
  BRDFKIT_REQUIRE_DATA("published-fits/ngan2005");
  std::array<std::vector<double>, 3> per_channel;
  for (const char* file : kNganFiles) {
    const auto fits = PublishedFits::read(ngan_dir() / file);
    for (const auto& mat : fits.materials()) {
      const Rgb a = albedo(fits.brdf(mat)), b = others().bagher.at(mat);
      for (int c = 0; c < 3; ++c) per_channel[size_t(c)].push_back(a[c] / b[c]);
    }
  }
  for (int c = 0; c < 3; ++c) {
    const double m = median(per_channel[size_t(c)]);
    std::cout << "[ channel  ] " << "RGB"[c] << ": Ngan / Bagher median " << m << "\n";
    EXPECT_NEAR(m, 1.0, 0.1) << "channel " << c;
  }
  // Specular albedo (albedo − kd) of each model's fit over Ward's fit of the material: Ngan fitted
  // every model to the same data, so the median is near 1 once each lobe's factor is right (4/π for
  // Cook-Torrance, 4 for Blinn-Phong, whose mirror-vector reading would give a quarter of it); a
  // factor 4 off gives 0.25 or 4. Measured: 0.70 to 1. Lafortune's is printed, not bounded: its
  // fits have |Cxy| > Cz, a lobe that grows towards grazing, attenuated at θi = 30° by
  // (C·(u∘v) / max(|Cxy|, |Cz|))ⁿ (nickel: 0.9935³⁷⁷ = 0.09), so its specular albedo there is not
  // its scale (median 0.12 of Ward's).
  const auto ward = PublishedFits::read(ngan_dir() / "ngan_ward.fit");
  const auto specular = [](const Brdf& b) {
    const int kd = find_param(b.model().params(), "kd");
    Rgb a = albedo(b);
    for (int c = 0; c < 3; ++c) a[c] -= b.values().values[size_t(c)][size_t(kd)];
    return luminance(a);
  };
  for (const char* file : kNganFiles) {
    const auto fits = PublishedFits::read(ngan_dir() / file);
    std::vector<double> ratios;
    for (const auto& mat : fits.materials()) ratios.push_back(specular(fits.brdf(mat)) / specular(ward.brdf(mat)));
    std::cout << "[ specular ] " << file << ": specular albedo / Ward's, median " << median(ratios) << "\n";
    if (std::string(file) == "ngan_lafortune.fit") continue;
    EXPECT_GT(median(ratios), 0.6) << file;
    EXPECT_LT(median(ratios), 1.6) << file;
  }
}

// The Lambertian reading: `Lambertian(albedo = a)` is ρ = a/π (albedo a), not ρ = a. On the
// materials where the diffuse term carries most of the albedo (kd ≥ half of it, every model), the
// albedo over Bagher's is near 1 read as a/π and near π read as a.
TEST(NganPublishedFits, LambertianAlbedoIsAOverPi) {
  BRDFKIT_REQUIRE_DATA("published-fits/ngan2005");
  std::vector<double> as_published, as_rho;
  for (const char* file : kNganFiles) {
    const auto fits = PublishedFits::read(ngan_dir() / file);
    for (const auto& mat : fits.materials()) {
      const Brdf b = fits.brdf(mat);
      const int kd = find_param(b.model().params(), "kd");
      const Rgb a = albedo(b);
      Rgb diffuse;
      for (int c = 0; c < 3; ++c) diffuse[c] = b.values().values[size_t(c)][size_t(kd)];
      if (luminance(diffuse) < 0.5 * luminance(a)) continue;
      const double bagher = luminance(others().bagher.at(mat));
      as_published.push_back(luminance(a) / bagher);
      as_rho.push_back(luminance(a + (kPi - 1) * diffuse) / bagher);  // kd/π → kd: the albedo gains (π − 1) kd
    }
  }
  std::cout << "[ lambert  ] " << as_published.size() << " diffuse-dominated fits: albedo / Bagher's, median "
            << median(as_published) << " read as a/pi, " << median(as_rho) << " read as a\n";
  ASSERT_GT(as_published.size(), 50u);
  EXPECT_NEAR(median(as_published), 1.0, 0.1);
  EXPECT_GT(median(as_rho), 2.0);
}

// He's wavelengths: R, G, B at 0.645, 0.526, 0.444 µm (core/vec.h, BBM's NganHe). Most of Ngan's He
// fits lie in the geometric-optics regime (σ0/λ ≫ 1), where the wavelength hardly moves the lobe;
// on the fits where it does (R and B read at each other's wavelength change the mirror-pair value
// at θ = 30° by more than 10 %: 28 of 172), the stated wavelengths bring that value nearer Bagher's
// fit of the material than the reversed ones do: median |log| of the ratio 1.24 against 1.51, R and
// B pooled (weak evidence: a sharp lobe's mirror value differs between any two models' fits by
// factors, here ~3.5).
TEST(NganPublishedFits, HeWavelengthsAreThoseOfTheChannels) {
  BRDFKIT_REQUIRE_DATA("published-fits/ngan2005");
  const auto fits = PublishedFits::read(ngan_dir() / "ngan_he.fit");
  const auto bagher = PublishedFits::read(fits_dir() / "bagher2012-sgd.json");
  const Vec3d wi = spherical_direction(30 * kPi / 180, 0.0), wo = spherical_direction(30 * kPi / 180, kPi);
  std::vector<double> stated, reversed;
  size_t fits_checked = 0;
  for (const auto& mat : fits.materials())
    for (int c : {0, 2}) {
      const Brdf b = fits.brdf(mat);
      ++fits_checked;
      // Model::eval takes the wavelength from the channel index: channel 2 − c's is the reversed one.
      const double s = b.model().eval(b.values().channel(c), c, wi, wo);
      const double r = b.model().eval(b.values().channel(c), 2 - c, wi, wo);
      if (std::abs(r - s) < 0.1 * s) continue;
      const double want = bagher.brdf(mat).eval(wi, wo)[c];
      stated.push_back(std::abs(std::log(s / want)));
      reversed.push_back(std::abs(std::log(r / want)));
    }
  std::cout << "[ he       ] " << stated.size() << " of " << fits_checked
            << " (material, R|B) fits move by > 10 % with the wavelength; |log(value / Bagher's)| median "
            << median(stated) << " stated, " << median(reversed) << " reversed\n";
  ASSERT_GE(stated.size(), 5u);
  EXPECT_LT(median(stated), median(reversed));
}

}  // namespace
}  // namespace brdfkit
