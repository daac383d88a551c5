// `brdfkit import-fits`: Ngan 2005's BBM text files written as published-fit JSON that loads to
// the same BRDF as the text file itself; bad input is one line naming the file, exit code 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/test_util.h"

namespace brdfkit {
namespace {

std::filesystem::path ngan_dir() { return test::data_dir() / "published-fits" / "ngan2005"; }

TEST(ImportFitsCli, JsonLoadsAsTheTextFile) {
  BRDFKIT_REQUIRE_DATA("published-fits/ngan2005");
  const auto dir = test::scratch_dir("import_fits");
  for (const char* name : {"ngan_ashikhminshirley", "ngan_he", "ngan_lafortune"}) {
    const auto text = ngan_dir() / (std::string(name) + ".fit"), json = dir / (std::string(name) + ".json");
    const auto r = test::run_cli("import-fits " + text.string() + " -o " + json.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("86 materials"), std::string::npos) << r.out;
    const std::string pairs = " --material nickel --wi 30 0 --wo 40 180";
    const auto from_text = test::run_cli("eval --params " + text.string() + pairs);
    const auto from_json = test::run_cli("eval --params " + json.string() + pairs);
    ASSERT_EQ(from_text.exit_code, 0) << from_text.err;
    EXPECT_EQ(from_text.out, from_json.out) << name;
  }
  std::filesystem::remove_all(dir);
}

TEST(ImportFitsCli, BadInputIsOneLine) {
  const auto dir = test::scratch_dir("import_fits_bad");
  std::ofstream(dir / "unknown.fit") << "x = Aggregate(Lambertian(albedo = [0.1, 0.1, 0.1]), Mystery(a = 1))\n";
  std::ofstream(dir / "broken.fit") << "x = Aggregate(Lambertian(albedo = [0.1, 0.1, 0.1])\n";
  std::ofstream(dir / "fits.json") << "{}\n";
  const struct {
    const char* file;
    const char* message;
  } cases[] = {{"unknown.fit", "unknown.fit: unsupported: unknown lobe 'Mystery'"},
               {"broken.fit", "broken.fit:1: expected ')' at column"},
               {"fits.json", "fits.json: is not a BBM .fit text file"}};
  for (const auto& c : cases) {
    const auto r = test::run_cli("import-fits " + (dir / c.file).string() + " -o " + (dir / "out.json").string());
    EXPECT_EQ(r.exit_code, 2) << c.file;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.json")) << c.file;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace brdfkit
