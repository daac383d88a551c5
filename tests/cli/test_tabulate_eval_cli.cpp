// `brdfkit tabulate` and `brdfkit eval`: what they write and print equals the
// library's evaluation of the same model and parameters, for --param values, sums of lobes,
// saved fits and published fits; the published-fit round trip through `brdfkit info`; bad input
// is a one-line message with exit code 2 and no file written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "brdfkit/analysis/model_checks.h"
#include "brdfkit/fit/fit_record.h"
#include "brdfkit/fit/param_source.h"
#include "brdfkit/measured/merl.h"
#include "brdfkit/models/published_fits.h"
#include "support/output_lines.h"
#include "support/test_util.h"

namespace brdfkit {
namespace {

namespace fs = std::filesystem;

fs::path published(const char* stem) { return test::data_dir() / "published-fits" / (std::string(stem) + ".json"); }

// Every 7th cell of the table against the library's value at the cell centre: the writer
// stores ρ/scale and the reader multiplies by scale, so they agree to rounding.
void expect_table_matches(const merl::Table& t, const Brdf& b, const std::string& what) {
  size_t compared = 0;
  double worst = 0;
  for (size_t k = 0; k < merl::kCellCount; k += 7) {
    Vec3d wi, wo;
    if (!merl::cell_directions(merl::cell_at(k), wi, wo)) {
      EXPECT_FALSE(t.valid(k));
      continue;
    }
    ASSERT_TRUE(t.valid(k)) << what << " cell " << k;
    const Rgb want = b.eval(wi, wo), got = t.value(k);
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(got[c] - want[c]) / std::max(want[c], 1e-300));
    ++compared;
  }
  EXPECT_LE(worst, 1e-14) << what;
  EXPECT_GT(compared, 150000u);
  std::printf("%s: %zu cells compared, worst relative difference %.3g\n", what.c_str(), compared, worst);
}

Rgb parse_rgb(const std::string& out) {
  std::istringstream in(out);
  Rgb v;
  in >> v[0] >> v[1] >> v[2];
  EXPECT_TRUE(bool(in)) << out;
  return v;
}

void expect_near_rel(const Rgb& got, const Rgb& want, double tol, const std::string& what) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], tol * std::abs(want[c])) << what << " channel " << c;
}

TEST(TabulateCli, PublishedFitThenInfo) {
  BRDFKIT_REQUIRE_DATA("published-fits");
  const fs::path dir = test::scratch_dir("tabulate_published");
  const fs::path out = dir / "pink-felt-sgd.binary";
  const auto r = test::run_cli("tabulate --params " + published("bagher2012-sgd").string() +
                               " --material pink-felt -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::lines_of(r.out).at(0), "wrote " + out.string() + ": cook-torrance-sgd-bagher2012 (material pink-felt)")
      << r.out;
  ASSERT_EQ(fs::file_size(out), merl::kFileBytes);
  const Brdf b = PublishedFits::read(published("bagher2012-sgd")).brdf("pink-felt");
  const merl::Table t = merl::read(out);
  expect_table_matches(t, b, "bagher2012-sgd pink-felt");

  // `info` reads it as a MERL file with every cell above the horizon measured; its albedo (a
  // quadrature of nearest-cell look-ups) agrees with the model's own albedo at θi = 30°.
  const auto info = test::run_cli("info " + out.string() + " --json");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const auto doc = nlohmann::json::parse(info.out);
  const auto& f = doc["files"][0];
  EXPECT_EQ(f["format"], "merl");
  EXPECT_EQ(f["valid"].get<size_t>(), t.valid_count());
  bool found = false;
  for (const auto& row : f["albedo"]) {
    if (std::abs(row["theta_i_deg"].get<double>() - 30) > 1e-9 || row["rgb"].is_null()) continue;
    found = true;
    for (int c = 0; c < 3; ++c) {
      const double want = albedo([&](const Vec3d& wi, const Vec3d& wo) { return b.eval(wi, wo)[c]; }, 30 * kPi / 180);
      const double got = row["rgb"][size_t(c)].get<double>();
      std::printf("pink-felt (SGD) albedo at 30 deg, channel %d: info %.6f, model %.6f\n", c, got, want);
      EXPECT_NEAR(got, want, 0.02 * want);
    }
  }
  EXPECT_TRUE(found) << info.out;
  fs::remove_all(dir);
}

TEST(TabulateCli, ModelWithParamsAndASum) {
  const fs::path dir = test::scratch_dir("tabulate_model");
  const fs::path out = dir / "sum.binary";
  const std::string model = "cook-torrance+cook-torrance";
  const std::vector<std::string> params{"kd=0.1,0.2,0.3", "1.alpha=0.3", "2.alpha=0.05", "2.ks[g]=0.7"};
  std::string args = "tabulate " + model + " -o " + out.string();
  for (const auto& p : params) args += " --param " + p;
  const auto r = test::run_cli(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Model& m = model_by_name(model);
  expect_table_matches(merl::read(out), Brdf(m, fit::params_from_args(m.params(), params)), model);
  fs::remove_all(dir);
}

TEST(EvalCli, PrintsRhoPerChannelAsTheLibrary) {
  const std::string model = "lambert+ward+blinn-phong";
  const Model& m = model_by_name(model);
  const std::vector<std::string> params{"kd=0.2,0.3,0.4", "2.alpha=0.2", "3.N=80"};
  const Brdf b(m, fit::params_from_args(m.params(), params));
  std::string p;
  for (const auto& a : params) p += " --param " + a;
  const Rgb want = b.eval(spherical_direction(30 * kPi / 180, 0.0), spherical_direction(35 * kPi / 180, kPi));
  auto r = test::run_cli("eval " + model + p + " --wi 30,0 --wo 35,180");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_near_rel(parse_rgb(r.out), want, 1e-9, "degrees");
  r = test::run_cli("eval " + model + p + " --wi 0.5235987755982988,0 --wo 0.6108652381980153,3.141592653589793 --radians");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_near_rel(parse_rgb(r.out), want, 1e-9, "radians");
  r = test::run_cli("eval " + model + p + " --wi 30,0 --wo 35,180 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["model"], model);
  for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(j["rho"][size_t(c)].get<double>(), want[c]);
  EXPECT_DOUBLE_EQ(j["params"]["3.N"][0].get<double>(), 80.0);
  std::printf("eval %s at (30,0), (35,180): %.10g %.10g %.10g\n", model.c_str(), want[0], want[1], want[2]);
}

TEST(EvalCli, PublishedAndSavedFits) {
  BRDFKIT_REQUIRE_DATA("published-fits");
  const Vec3d wi = spherical_direction(20 * kPi / 180, 0.0), wo = spherical_direction(25 * kPi / 180, kPi);
  for (const char* stem : {"bagher2012-sgd", "low2012-smooth-E2", "low2012-cooktorrance-E1",
                           "low2012-ashikhminshirley-E2"}) {
    const auto r = test::run_cli("eval --params " + published(stem).string() + " --material gold-metallic-paint"
                                 " --wi 20,0 --wo 25,180");
    ASSERT_EQ(r.exit_code, 0) << stem << ": " << r.err;
    expect_near_rel(parse_rgb(r.out), PublishedFits::read(published(stem)).brdf("gold-metallic-paint").eval(wi, wo),
                    1e-9, stem);
  }
  // A saved fit of a sum, read back by `eval`, with one value overridden by --param.
  const fs::path dir = test::scratch_dir("eval_fit");
  const Model& m = model_by_name("cook-torrance+cook-torrance");
  fit::FitRecord rec;
  rec.model = std::string(m.name());
  rec.values = fit::params_from_args(m.params(), {"kd=0.05,0.1,0.15", "2.alpha=0.04"});
  fit::save_fit_record(dir / "fit.json", rec);
  auto r = test::run_cli("eval --params " + (dir / "fit.json").string() + " --wi 20,0 --wo 25,180");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_near_rel(parse_rgb(r.out), Brdf(m, rec.values).eval(wi, wo), 1e-9, "saved fit");
  r = test::run_cli("eval --params " + (dir / "fit.json").string() + " --param kd=0.5 --wi 20,0 --wo 25,180");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ParamValues v = rec.values;
  v.set(m.params(), "kd", 0.5);
  expect_near_rel(parse_rgb(r.out), Brdf(m, v).eval(wi, wo), 1e-9, "saved fit with --param");
  fs::remove_all(dir);
}

// A sum works through `models`, `check` and `fit` as any model does.
TEST(SumCli, ModelsCheckAndFit) {
  auto r = test::run_cli("models cook-torrance+cook-torrance --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.size(), 1u);
  std::vector<std::string> names;
  for (const auto& p : j[0]["params"]) names.push_back(p["name"].get<std::string>());
  EXPECT_EQ(names, (std::vector<std::string>{"kd", "1.ks", "1.alpha", "1.F0", "2.ks", "2.alpha", "2.F0"}));

  r = test::run_cli("check lambert+ward+blinn-phong --param 3.N=100 --samples 20000 --theta-o 0 --theta-o 60");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;

  const fs::path dir = test::scratch_dir("sum_fit_cli");
  r = test::run_cli("tabulate cook-torrance+cook-torrance --param 1.alpha=0.3 --param 2.alpha=0.05 -o " +
                    (dir / "m.binary").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = test::run_cli("fit " + (dir / "m.binary").string() + " --model cook-torrance+cook-torrance --metric ngan "
                    "--coarsen 4 --report ngan -o " + (dir / "fit.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const Brdf fitted = fit::load_params_file(dir / "fit.json", "");
  EXPECT_EQ(fitted.model().name(), "cook-torrance+cook-torrance");
  const double a1 = fitted.values().values[0][size_t(find_param(fitted.model().params(), "1.alpha"))];
  const double a2 = fitted.values().values[0][size_t(find_param(fitted.model().params(), "2.alpha"))];
  std::printf("CLI fit of a tabulated two-lobe Cook-Torrance: 1.alpha %.5g (true 0.3), 2.alpha %.5g (true 0.05)\n", a1, a2);
  // The lobes are interchangeable (same model, one kd): the fit may return them in either order.
  EXPECT_NEAR(std::max(a1, a2), 0.3, 0.03);
  EXPECT_NEAR(std::min(a1, a2), 0.05, 0.005);
  fs::remove_all(dir);
}

TEST(TabulateCli, BadInputIsAOneLineErrorAndWritesNothing) {
  const fs::path dir = test::scratch_dir("tabulate_bad");
  const std::string out = (dir / "x.binary").string();
  struct Case {
    std::string args, expect;
  };
  std::vector<Case> cases = {
      {"tabulate nope -o " + out, "unknown"},
      {"tabulate ward --param alpha=-1 -o " + out, "outside"},
      {"tabulate ward --param beta=1 -o " + out, "beta"},
      {"tabulate ward --param kd=0.1,0.2 -o " + out, "three comma-separated"},
      {"tabulate -o " + out, "give a model name or a parameter file"},
      {"tabulate ward --material chrome -o " + out, "--material"},
      {"eval ward --wi 95,0 --wo 10,0", "--wi"},
      {"eval ward --wi 10,0", "--wo"},
      {"tabulate --params " + (dir / "missing.json").string() + " -o " + out, "missing.json"},
  };
  if (fs::exists(published("bagher2012-sgd"))) {
    cases.push_back({"tabulate --params " + published("bagher2012-sgd").string() + " --material pink-felts -o " + out,
                     "pink-felt"});  // the closest names are listed
    cases.push_back({"tabulate --params " + published("bagher2012-sgd").string() + " -o " + out, "--material"});
    cases.push_back({"tabulate ward --params " + published("bagher2012-sgd").string() + " -o " + out, "not both"});
  }
  for (const auto& c : cases) {
    const auto r = test::run_cli(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace brdfkit
