// Spectrum → linear sRGB, brdfkit's convention (DESIGN.md §2), against independent sums over the
// CIE tables of ../shared/data/cie.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/spectral_rgb.h"
#include "support/real_data.h"

using namespace brdfkit;
using namespace brdfkit::test;

namespace {

std::vector<std::vector<double>> csv(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || !std::isdigit(static_cast<unsigned char>(line[0]))) continue;
    std::vector<double> r;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) r.push_back(std::stod(cell));
    rows.push_back(r);
  }
  return rows;
}

std::vector<double> cornell_wavelengths() {
  std::vector<double> wl;
  for (int k = 0; k <= 30; ++k) wl.push_back(400 + 10 * k);
  return wl;
}

}  // namespace

TEST(SpectralRgb, ConstantSpectrumOfOneIsWhite) {
  BRDFKIT_REQUIRE_DATA("cie");
  const SpectrumToRgb conv(data_dir() / "cie");
  const auto wl = cornell_wavelengths();
  const std::vector<double> ones(wl.size(), 1.0);
  const Rgb rgb = conv.rgb(wl, ones);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c], 1.0, 2e-4);
  const Eigen::Vector3d xyz = conv.xyz(wl, ones);  // the D65 white point, Y = 1
  EXPECT_NEAR(xyz[0], 0.9505, 5e-4);
  EXPECT_NEAR(xyz[1], 1.0, 1e-12);
  EXPECT_NEAR(xyz[2], 1.089, 1e-3);
}

// DESIGN.md §2: pbrt-v2 weighted with an equal-energy illuminant and no adaptation, which turns
// white into (1.205, 0.948, 0.909). Same tables, the IEC matrix, E instead of D65.
TEST(SpectralRgb, EqualEnergyWeightingGivesPbrtV2White) {
  BRDFKIT_REQUIRE_DATA("cie");
  const auto cmf = csv(data_dir() / "cie" / "cie1931-2deg-xyz-1nm.csv");
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  for (const auto& r : cmf) xyz += Eigen::Vector3d(r[1], r[2], r[3]);
  xyz /= xyz[1];
  const Eigen::Vector3d rgb = xyz_to_linear_srgb() * xyz;
  EXPECT_NEAR(rgb[0], 1.205, 1e-3);
  EXPECT_NEAR(rgb[1], 0.948, 1e-3);
  EXPECT_NEAR(rgb[2], 0.909, 1e-3);
}

// A non-constant spectrum against a direct per-nanometre sum written here independently: hold
// constant outside 400–700 nm, linear in between, D65 interpolated from 5 nm.
TEST(SpectralRgb, RampSpectrumMatchesDirectSum) {
  BRDFKIT_REQUIRE_DATA("cie");
  const auto cmf = csv(data_dir() / "cie" / "cie1931-2deg-xyz-1nm.csv");
  const auto d65 = csv(data_dir() / "cie" / "cie-d65-5nm.csv");
  const auto wl = cornell_wavelengths();
  std::vector<double> s;
  for (double l : wl) s.push_back(0.1 + 0.8 * (l - 400) / 300 + 0.05 * std::sin(l / 17));
  auto spectrum = [&](double l) {
    if (l <= 400) return s.front();
    if (l >= 700) return s.back();
    const size_t j = size_t((l - 400) / 10);
    const double t = (l - wl[j]) / 10;
    return (1 - t) * s[j] + t * s[std::min(j + 1, s.size() - 1)];
  };
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  double norm = 0;
  for (const auto& r : cmf) {
    const double l = r[0];
    const size_t j = size_t((l - 300) / 5);
    const double t = (l - d65[j][0]) / 5;
    const double e = t > 0 ? (1 - t) * d65[j][1] + t * d65[j + 1][1] : d65[j][1];
    xyz += spectrum(l) * e * Eigen::Vector3d(r[1], r[2], r[3]);
    norm += e * r[2];
  }
  xyz /= norm;
  const SpectrumToRgb conv(data_dir() / "cie");
  const Eigen::Vector3d mine = conv.xyz(wl, s);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(mine[c], xyz[c], 1e-12 + 1e-10 * std::abs(xyz[c]));
  const Rgb rgb = conv.rgb(wl, s);
  const Eigen::Vector3d expected = xyz_to_linear_srgb() * xyz;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c], expected[c], 1e-10);
}

TEST(SpectralRgb, MissingTablesAreAnInputError) {
  const auto dir = scratch_dir("no_cie");
  EXPECT_THROW(SpectrumToRgb{dir}, InputError);
  const auto wl = cornell_wavelengths();
  BRDFKIT_REQUIRE_DATA("cie");
  const SpectrumToRgb conv(data_dir() / "cie");
  const std::vector<double> too_few(3, 1.0);
  EXPECT_THROW(conv.rgb(wl, too_few), InputError);
}
