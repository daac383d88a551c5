// The CIE tables compiled into brdfkit (the repository's resources/cie/) and their folder override
// $BRDFKIT_CIE_DIR (spectral_rgb.h): spectral data convert wherever the data file lies.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/spectral_rgb.h"
#include "support/test_util.h"

using namespace brdfkit;
using namespace brdfkit::test;

namespace {

std::vector<double> cornell_wavelengths() {
  std::vector<double> wl;
  for (int k = 0; k <= 30; ++k) wl.push_back(400 + 10 * k);
  return wl;
}

// Tables of a flat observer and a flat illuminant (every value 1): XYZ of a constant spectrum 1 is
// then (1, 1, 1), so its RGB is the row sums of the sRGB matrix, far from the built-in white.
std::filesystem::path write_flat_tables(const std::filesystem::path& dir) {
  std::ofstream cmf(dir / "cie1931-2deg-xyz-1nm.csv"), d65(dir / "cie-d65-5nm.csv");
  cmf << "# flat test observer\nlambda_nm,xbar,ybar,zbar\n";
  for (int nm = 360; nm <= 830; ++nm) cmf << nm << ",1,1,1\n";
  d65 << "# flat test illuminant\nlambda_nm,power\n";
  for (int nm = 300; nm <= 830; nm += 5) d65 << nm << ",1\n";
  return dir;
}

}  // namespace

// Without any file: the compiled-in tables turn a constant spectrum of 1 into white (DESIGN.md §2).
TEST(CieTables, BuiltInTablesNeedNoFiles) {
  const ScopedEnv no_override("BRDFKIT_CIE_DIR", nullptr);
  const auto wl = cornell_wavelengths();
  const std::vector<double> ones(wl.size(), 1.0);
  for (const SpectrumToRgb* conv : {&default_spectrum_to_rgb(), &built_in_spectrum_to_rgb()}) {
    const Rgb rgb = conv->rgb(wl, ones);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c], 1.0, 2e-4);
  }
}

// The compiled-in tables are the shared data's cie/ tables: the same numbers, bit for bit.
TEST(CieTables, BuiltInTablesEqualTheSharedOnes) {
  BRDFKIT_REQUIRE_DATA("cie");
  const SpectrumToRgb& built_in = built_in_spectrum_to_rgb();
  const SpectrumToRgb shared(data_dir() / "cie");
  const std::vector<std::vector<double>> samplings = {cornell_wavelengths(), {400, 500, 600, 700}, {555}, {380, 381.5, 790}};
  for (const auto& wl : samplings) {
    const Eigen::MatrixXd a = built_in.matrix(wl), b = shared.matrix(wl);
    ASSERT_EQ(a.cols(), b.cols());
    EXPECT_TRUE((a.array() == b.array()).all()) << "built-in\n" << a << "\nshared\n" << b;
  }
}

TEST(CieTables, EnvironmentFolderOverridesTheBuiltInTables) {
  const auto dir = write_flat_tables(scratch_dir("cie_flat"));
  const ScopedEnv override_dir("BRDFKIT_CIE_DIR", dir.c_str());
  const auto wl = cornell_wavelengths();
  const std::vector<double> ones(wl.size(), 1.0);
  const Rgb rgb = default_spectrum_to_rgb().rgb(wl, ones);
  const Eigen::Vector3d row_sums = xyz_to_linear_srgb() * Eigen::Vector3d::Ones();
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c], row_sums[c], 1e-12);
  std::filesystem::remove_all(dir);
}

TEST(CieTables, EnvironmentFolderWithoutTablesIsAnInputError) {
  const auto dir = scratch_dir("cie_empty");
  const ScopedEnv override_dir("BRDFKIT_CIE_DIR", dir.c_str());
  try {
    default_spectrum_to_rgb();
    ADD_FAILURE() << "an override folder without tables was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("BRDFKIT_CIE_DIR"), std::string::npos) << what;
    EXPECT_NE(what.find(dir.string()), std::string::npos) << what;
    EXPECT_NE(what.find("cie1931-2deg-xyz-1nm.csv"), std::string::npos) << what;
  }
  std::filesystem::remove_all(dir);
}
