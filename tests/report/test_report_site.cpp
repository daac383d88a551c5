// The report of a small fit-all (one Cornell material and one MERL file brdfkit tabulates, three
// fast models) loads in headless Chromium (Debian's chromium through playwright-core) with no
// console error, every image and chart present and every link resolving (check_report.mjs);
// screenshots of the index and of a material page are saved in <build>/report-screenshots. With
// one render PNG deleted the same check fails, naming it. The seed claims count and divide right.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "brdfkit/report/seed_claims.h"
#include "support/real_data.h"
#include "support/test_util.h"

namespace brdfkit::report {
namespace {

namespace fs = std::filesystem;

bool have(const char* command) { return std::system((std::string("command -v ") + command + " >/dev/null 2>&1").c_str()) == 0; }

test::CliResult check_site(const fs::path& site, const fs::path& shots) {
  const std::string cmd = "cd " + std::string(BRDFKIT_SOURCE_DIR) + " && node tests/report/check_report.mjs " + site.string() +
                          " " + shots.string();
  const auto out = test::scratch_dir("check_out") / "log";
  const int status = std::system((cmd + " >" + out.string() + " 2>&1").c_str());
  std::ifstream in(out);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, std::string(std::istreambuf_iterator<char>(in), {}), ""};
}

TEST(ReportSite, LoadsInHeadlessChromiumAndFailsWithoutAnImage) {
  BRDFKIT_REQUIRE_DATA("cornell");
  if (!have("node") || !have("/usr/bin/chromium") || !fs::exists(fs::path(BRDFKIT_SOURCE_DIR) / "node_modules/playwright-core"))
    GTEST_SKIP() << "node, /usr/bin/chromium or node_modules/playwright-core is missing (scripts/setup.sh installs them)";
  const fs::path dir = test::scratch_dir("report");
  const fs::path merl = dir / "data" / "ggx_tabulated.binary";
  fs::create_directories(merl.parent_path());
  ASSERT_EQ(test::run_cli("tabulate cook-torrance-ggx --param kd=0.3,0.2,0.1 --param alpha=0.15 -o " + merl.string()).exit_code, 0);
  const auto fa = test::run_cli("fit-all " + test::cornell_file("garnet_red").string() + " " + merl.string() +
                                " --models cook-torrance-ggx,blinn-phong,lambert --jobs 2 -o " + (dir / "fits").string());
  ASSERT_EQ(fa.exit_code, 0) << fa.err;
  const auto rep = test::run_cli("report " + (dir / "fits").string() + " --size 64 --spp 8 -q");
  ASSERT_EQ(rep.exit_code, 0) << rep.err;
  const fs::path index = dir / "fits" / "report" / "index.html";
  EXPECT_EQ(rep.out, fs::absolute(index).lexically_normal().string() + "\n");
  const fs::path shots = fs::path(BRDFKIT_CLI_PATH).parent_path() / "report-screenshots";
  const auto ok = check_site(dir / "fits" / "report", shots);
  EXPECT_EQ(ok.exit_code, 0) << ok.out;
  EXPECT_NE(ok.out.find("report OK: 3 pages"), std::string::npos) << ok.out;
  EXPECT_TRUE(fs::exists(shots / "index.png") && fs::exists(shots / "material.png"));
  std::printf("%sscreenshots: %s/index.png, material.png\n", ok.out.c_str(), shots.c_str());

  // Take away the tabulated material's measured render: the check must fail and name it.
  const fs::path png = dir / "fits" / "report" / "materials" / "ggx_tabulated" / "render-0.png";
  ASSERT_TRUE(fs::exists(png));
  fs::remove(png);
  const auto broken = check_site(dir / "fits" / "report", dir / "shots-broken");
  EXPECT_EQ(broken.exit_code, 1) << broken.out;
  EXPECT_NE(broken.out.find("image missing or undecodable: ggx_tabulated/render-0.png"), std::string::npos) << broken.out;
  std::printf("with render-0.png deleted: %s", broken.out.substr(broken.out.find("PROBLEM")).c_str());
  fs::remove_all(dir);
}

FitResult fake_fit(const std::string& model, double ngan) {
  const Model& m = model_by_name(model);
  return {model, "", {{"metrics", {{"ngan", ngan}}}}, Brdf(m, ParamValues::defaults(m.params()))};
}

TEST(SeedClaims, CountsAndMedianRatio) {
  BatchResults b;
  b.fit_metric = "ngan";
  const double sgd[3] = {0.01, 0.04, 0.02}, beckmann[3] = {0.02, 0.02, 0.08};
  for (int k = 0; k < 3; ++k)
    b.materials.push_back({"m" + std::to_string(k), "", {fake_fit("cook-torrance-sgd", sgd[k]), fake_fit("cook-torrance-beckmann", beckmann[k])}});
  b.materials.push_back({"only-one", "", {fake_fit("cook-torrance-sgd", 0.5)}});
  const auto claims = measure_seed_claims(b);
  ASSERT_EQ(claims.size(), 1u);  // the other claims' pairs were not fitted
  EXPECT_EQ(claims[0].model_a, "cook-torrance-sgd");
  EXPECT_EQ(claims[0].materials, 3);
  EXPECT_EQ(claims[0].a_better, 2);
  EXPECT_DOUBLE_EQ(claims[0].median_ratio, 0.5);  // ratios 0.5, 2, 0.25
}

}  // namespace
}  // namespace brdfkit::report
