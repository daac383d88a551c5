// `brdfkit fit` and `brdfkit error`: a saved fit reproduces its numbers, outputs never hold NaN,
// bad input exits with 2 and a message naming the problem.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "brdfkit/core/error.h"
#include "brdfkit/core/file_digest.h"
#include "brdfkit/measured/merl.h"
#include "support/fit_test_util.h"
#include "support/test_util.h"

namespace brdfkit::test {
namespace {

// The "metrics" block of the human output.
std::string metric_lines(const std::string& out) {
  const auto at = out.find("metrics\n");
  if (at == std::string::npos) return "";
  std::string block;
  std::istringstream in(out.substr(at + 8));
  std::string line;
  while (std::getline(in, line) && line.rfind("  ", 0) == 0) block += line + "\n";
  return block;
}

class CliFit : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::filesystem::path(scratch_dir("cli_fit"));
    const Model& m = model_by_name("cook-torrance-beckmann");
    const ParamValues v = make_values(m, {{"kd", Rgb(0.1, 0.2, 0.3)},
                                          {"ks", Rgb(0.5, 0.5, 0.5)},
                                          {"alpha", Rgb::Constant(0.25)},
                                          {"F0", Rgb::Constant(0.05)}});
    merl::write(*dir_ / "ct.binary", tabulate_model(m, v, 0.05, 0.01));
  }
  static void TearDownTestSuite() {
    std::filesystem::remove_all(*dir_);
    delete dir_;
  }
  static std::string path(const char* name) { return (*dir_ / name).string(); }
  static std::filesystem::path* dir_;
};
std::filesystem::path* CliFit::dir_ = nullptr;

TEST_F(CliFit, FitThenErrorReproducesEveryNumber) {
  const std::string metrics = "ngan,bagher,low-e1,low-e2";
  const auto fit = run_cli("fit " + path("ct.binary") + " --model cook-torrance-beckmann --coarsen 2 --report " +
                           metrics + " -o " + path("fit.json"));
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  const auto err = run_cli("error " + path("ct.binary") + " --params " + path("fit.json") + " --metric " + metrics);
  ASSERT_EQ(err.exit_code, 0) << err.err;
  const std::string a = metric_lines(fit.out), b = metric_lines(err.out);
  EXPECT_EQ(std::count(a.begin(), a.end(), '\n'), 4) << fit.out;
  EXPECT_EQ(a, b);
  EXPECT_EQ(fit.out.find("nan"), std::string::npos) << fit.out;
  EXPECT_EQ(err.err, "");  // same file: no checksum warning

  // The saved JSON: schema fields, the data's SHA-256, and the values `error --json` recomputes bit for bit.
  std::ifstream in(path("fit.json"));
  const nlohmann::json saved = nlohmann::json::parse(in);
  EXPECT_EQ(saved["model"], "cook-torrance-beckmann");
  EXPECT_EQ(saved["brdfkit_version"], BRDFKIT_VERSION);
  EXPECT_EQ(saved["data"]["sha256"], sha256_file(path("ct.binary")));
  EXPECT_EQ(saved["params"].size(), 4u);
  const auto ej = run_cli("error " + path("ct.binary") + " --params " + path("fit.json") + " --metric " + metrics +
                          " --json");
  ASSERT_EQ(ej.exit_code, 0) << ej.err;
  const nlohmann::json recomputed = nlohmann::json::parse(ej.out);
  for (const char* id : {"ngan", "bagher", "low-e1", "low-e2"}) {
    ASSERT_TRUE(saved["metrics"][id].is_number()) << id;
    EXPECT_EQ(saved["metrics"][id].get<double>(), recomputed["metrics"][id].get<double>()) << id;
  }
  const double alpha = saved["params"][2]["values"][0];
  EXPECT_NEAR(alpha, 0.25, 0.25 * 5e-2);  // nearest-cell quantization: see test_recovery.cpp
}

TEST_F(CliFit, ErrorWarnsWhenTheDataFileDiffers) {
  const auto fit = run_cli("fit " + path("ct.binary") + " --model lambert --coarsen 4 --report ngan -o " +
                           path("lambert.json"));
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  const Model& m = model_by_name("lambert");
  merl::write(*dir_ / "other.binary", tabulate_model(m, make_values(m, {{"kd", Rgb(0.3, 0.3, 0.3)}})));
  const auto err = run_cli("error " + path("other.binary") + " --params " + path("lambert.json") + " --metric ngan");
  EXPECT_EQ(err.exit_code, 0);
  EXPECT_EQ(err.err, "brdfkit: warning: " + path("other.binary") + " is not the file this fit was made on (sha256 " +
                         sha256_file(path("other.binary")) + " != " + sha256_file(path("ct.binary")) + ")\n");
}

TEST_F(CliFit, BadInputsExitWithTwoAndNameTheProblem) {
  const std::string data = path("ct.binary");
  std::ofstream(path("garbage.json")) << "{not json";
  std::ofstream(path("notnum.json")) << R"({"model": "lambert", "params": [{"name": "kd", "values": [0.1, "x", 0.2]}]})";
  std::ofstream(path("bounds.json")) << R"({"model": "lambert", "params": [{"name": "kd", "values": [0.1, -7, 0.2]}]})";
  // hp-rmse's grid is too large to keep for a fit (on a MERL table it has the cells).
  ASSERT_EQ(run_cli("convert lambert --param kd=0.3 -o " + path("lambert.bsdf")).exit_code, 0);
  const std::pair<std::string, std::string> cases[] = {
      {"fit " + path("missing.binary") + " --model lambert -o " + path("x.json"), "missing.binary"},
      {"fit " + data + " --model no-such-model -o " + path("x.json"), "no-such-model"},
      {"fit " + data + " --model lambert --metric rmse -o " + path("x.json"), "rmse"},
      {"fit " + data + " --model lambert --starts 0 -o " + path("x.json"), "--starts"},
      {"fit " + path("lambert.bsdf") + " --model lambert --metric hp-rmse --coarsen 8 -o " + path("x.json"), "hp-rmse"},
      {"fit " + data + " --model lambert --coarsen 0 -o " + path("x.json"), "coarsen"},
      {"error " + data + " --params " + path("none.json"), "none.json"},
      {"error " + data + " --params " + path("garbage.json"), "garbage.json"},
      {"error " + data + " --params " + path("notnum.json"), "values[1]"},
      {"error " + data + " --params " + path("bounds.json"), "outside the formula's domain"},
  };
  for (const auto& [args, needle] : cases) {
    const auto r = run_cli(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << args << "\n" << r.err;
    EXPECT_EQ(r.err.find("nan"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(path("x.json")));
}

TEST(FileDigest, Sha256MatchesTheSharedChecksumList) {
  BRDFKIT_REQUIRE_DATA("rgl");
  std::ifstream sums(data_dir() / "SHA256SUMS");
  std::string sum, file;
  int checked = 0;
  while (sums >> sum >> file && checked < 2)
    if (file.rfind("rgl/", 0) == 0) {
      EXPECT_EQ(sha256_file(data_dir() / file), sum) << file;
      ++checked;
    }
  EXPECT_EQ(checked, 2);
  EXPECT_THROW(sha256_file(data_dir() / "no-such-file"), InputError);
}

}  // namespace
}  // namespace brdfkit::test
