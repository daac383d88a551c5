// `brdfkit info` on copies of a real RGL file with one table made invalid: the command must exit
// with code 2 and a one-line message naming the file, the field and the first bad index, never
// crash or print nan/inf. Skipped with a printed reason when ../shared/data/rgl is absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "support/real_data.h"

using namespace brdfkit;
using namespace brdfkit::test;
namespace fs = std::filesystem;

namespace {

constexpr const char* kMaterial = "colodur_napoli_4f";

// Runs `info` on `file` and checks the refusal: exit 2, one line, file, field and `index_text`;
// then removes the file's scratch folder.
void expect_info_refuses(const fs::path& file, const std::string& field, const std::string& index_text) {
  const auto r = run_cli("info '" + file.string() + "'");
  std::printf("exit %d, stderr: %s", r.exit_code, r.err.c_str());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("brdfkit: " + file.string() + ": "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("field '" + field + "'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(index_text), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("inf"), std::string::npos) << r.out;
  fs::remove_all(file.parent_path());
}

}  // namespace

TEST(RglValidationCli, NegativeThetaIIsRefusedNotACrash) {
  BRDFKIT_REQUIRE_DATA("rgl");
  const auto file = rgl_variant(kMaterial, scratch_dir("rgl_cli_theta") / "negative_theta.bsdf",
                                [](auto& fields) { set_float(fields, "theta_i", 0, -0.1f); });
  expect_info_refuses(file, "theta_i", "entry 0 ");
}

TEST(RglValidationCli, NanInRgbIsRefused) {
  BRDFKIT_REQUIRE_DATA("rgl");
  // Entry 1234 of rgb[1,8,3,32,32] is θi node 0, channel G, row 6, column 18.
  const auto file = rgl_variant(kMaterial, scratch_dir("rgl_cli_nan") / "nan_rgb.bsdf", [](auto& fields) {
    set_float(fields, "rgb", 1234, std::numeric_limits<float>::quiet_NaN());
  });
  expect_info_refuses(file, "rgb", "entry 1234 [0,0,1,6,18] is NaN");
}

TEST(RglValidationCli, PlusInfInRgbIsRefused) {
  // Entry 5000 is θi node 1, channel G, row 28, column 8.
  BRDFKIT_REQUIRE_DATA("rgl");
  const auto file = rgl_variant(kMaterial, scratch_dir("rgl_cli_inf") / "inf_rgb.bsdf", [](auto& fields) {
    set_float(fields, "rgb", 5000, std::numeric_limits<float>::infinity());
  });
  expect_info_refuses(file, "rgb", "entry 5000 [0,1,1,28,8] is +Inf");
}

TEST(RglValidationCli, AllZeroSigmaIsRefused) {
  BRDFKIT_REQUIRE_DATA("rgl");
  const auto file = rgl_variant(kMaterial, scratch_dir("rgl_cli_sigma") / "zero_sigma.bsdf",
                                [](auto& fields) { fill_float(fields, "sigma", 0.0f); });
  expect_info_refuses(file, "sigma", "entry 0 [0,0] is 0");
}
