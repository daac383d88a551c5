// Each option of `brdfkit <subcommand> --help` changes what the command does. This file holds a
// test of the effect of every option no other test measures (most are checked where their
// subcommand is tested: test_tabulate_eval_cli.cpp, test_cli_fit.cpp, test_info_cli.cpp,
// test_render_cli.cpp, test_export_cli.cpp, test_convert_ndf_cli.cpp, tests/analysis/,
// tests/fit/batch/, tests/report/). Inputs are tiny (8-pixel renders, coarse metric grids) to keep
// the file short; data from ../shared/data are skipped with a printed reason when absent.
// `export --material` is in test_export_cli.cpp (its inputs, published fits, are always refitted).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "brdfkit/fit/fit_record.h"
#include "brdfkit/fit/param_source.h"
#include "brdfkit/measured/merl.h"
#include "brdfkit/measured/merl_tabulate.h"
#include "brdfkit/models/model_sets.h"
#include "brdfkit/models/published_fits.h"
#include "brdfkit/render/image_io.h"
#include "support/fit_test_util.h"
#include "support/output_lines.h"
#include "support/test_util.h"

namespace brdfkit {
namespace {

namespace fs = std::filesystem;
using test::run_cli;

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

nlohmann::json read_json(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

nlohmann::json stdout_json(const test::CliResult& r) { return nlohmann::json::parse(r.out); }

// Largest |a − b| / max(|a|, |b|, floor) over the pixels of two images of one size.
double max_relative_difference(const render::Image& a, const render::Image& b, double floor = 1e-6) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  double worst = 0;
  for (size_t k = 0; k < std::min(a.size(), b.size()); ++k)
    for (int c = 0; c < 3; ++c) {
      const double x = a.pixels[k][c], y = b.pixels[k][c];
      worst = std::max(worst, std::abs(x - y) / std::max({std::abs(x), std::abs(y), floor}));
    }
  return worst;
}

// Shared inputs: a MERL table whose channels have GGX lobes of different widths (α = 0.1, 0.2,
// 0.4), and a table with no measured cell.
class CliOptions : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(test::scratch_dir("cli_options"));
    const Model& m = model_by_name("cook-torrance-ggx");
    std::vector<Brdf> lobes;
    for (double alpha : {0.1, 0.2, 0.4})
      lobes.emplace_back(m, test::make_values(m, {{"kd", Rgb(0.1, 0.2, 0.3)},
                                                  {"ks", Rgb::Constant(0.5)},
                                                  {"alpha", Rgb::Constant(alpha)}}));
    merl::write(*dir_ / "widths.binary", merl::tabulate([&](const Vec3d& wi, const Vec3d& wo) {
                  return Rgb(lobes[0].eval(wi, wo)[0], lobes[1].eval(wi, wo)[1], lobes[2].eval(wi, wo)[2]);
                }));
    merl::write(*dir_ / "empty.binary", merl::Table());
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  static fs::path path(const std::string& name) { return *dir_ / name; }
  static std::string data() { return q(path("widths.binary")); }
  static inline fs::path* dir_ = nullptr;
};

TEST(CliVersion, PrintsTheBuildVersion) {
  const auto r = run_cli("--version");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, std::string("brdfkit ") + BRDFKIT_VERSION + "\n");
  EXPECT_EQ(r.err, "");
}

// info --jobs: threads only; the numbers do not depend on it (the real pink-felt slice).
TEST(CliInfo, JobsDoNotChangeTheResult) {
  BRDFKIT_REQUIRE_DATA("merl-slices");
  const std::string args = "info --json " + q(test::data_dir() / "merl-slices" / "pink-felt-1d.alta");
  const auto one = run_cli(args + " --jobs 1"), two = run_cli(args + " --jobs 2");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  ASSERT_EQ(two.exit_code, 0) << two.err;
  EXPECT_EQ(stdout_json(one), stdout_json(two));
  EXPECT_FALSE(stdout_json(one)["files"][0]["albedo"].empty());
}

// `check` exits 3 when a check fails. Cook-Torrance with α = 0.001 seen at θo = 89.99°: the
// χ² test of the sampler fails for a channel whose specular lobe carries the reflectance and
// passes for a purely diffuse one (cosine sampling is exact), so --channel shows which channel's
// values it tests: R (ks = 0) passes, B (kd = 0) fails. Normalization and reciprocity pass in both.
TEST(CliCheck, FailedCheckExitsThreeAndChannelPicksTheTestedValues) {
  const std::string args = "check cook-torrance --param kd=1,0.5,0 --param ks=0,0.5,1 --param alpha=0.001 "
                           "--theta-o 89.99 --samples 1000";
  const auto r = run_cli(args + " --channel 0 --json");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto ok = stdout_json(r);
  EXPECT_TRUE(ok["passed"].get<bool>());
  ASSERT_EQ(ok["chi2"].size(), 1u);
  EXPECT_EQ(ok["chi2"][0]["channel"], 0);
  EXPECT_GT(ok["chi2"][0]["p_value"].get<double>(), 0.01);

  const auto bad = run_cli(args + " --channel 2");
  ASSERT_EQ(bad.exit_code, 3) << bad.out << bad.err;
  EXPECT_TRUE(test::has_line(bad.out, "normalization  int D cos dw = 1.00000000")) << bad.out;
  const auto recip = test::line_led_by(bad.out, "reciprocity");
  ASSERT_TRUE(recip) << bad.out;
  EXPECT_LT(std::stod(test::tokens_of(*recip).at(4)), 1e-8) << *recip;
  const auto row = test::line_led_by(bad.out, "90");  // θo printed with no decimals
  ASSERT_TRUE(row) << bad.out;
  const auto t = test::tokens_of(*row);
  ASSERT_GE(t.size(), 7u) << *row;
  EXPECT_LT(std::stod(t[3]), 0.01) << *row;  // p-value
  EXPECT_EQ(t[6], "FAIL") << *row;
  EXPECT_EQ(test::lines_of(bad.out).back(), "some checks FAILED");
  std::printf("check at theta_o 89.99: channel 0 chi2 %.1f (p %.3f); channel 2: %s\n",
              ok["chi2"][0]["statistic"].get<double>(), ok["chi2"][0]["p_value"].get<double>(), row->c_str());
}

// --seed: the χ² draws repeat for one seed and change with another (Lambert: cosine sampling).
TEST(CliCheck, SeedRepeatsAndChangesTheDraws) {
  auto statistic = [](int seed) {
    const auto r = run_cli("check lambert --samples 1000 --theta-o 30 --json --seed " + std::to_string(seed));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return stdout_json(r)["chi2"][0]["statistic"].get<double>();
  };
  const double a = statistic(7), again = statistic(7), other = statistic(8);
  std::printf("lambert chi2 statistic: seed 7 %.6f, again %.6f, seed 8 %.6f\n", a, again, other);
  EXPECT_EQ(a, again);
  EXPECT_NE(a, other);
  const auto human = run_cli("check lambert --samples 1000 --theta-o 30 --seed 7");
  ASSERT_FALSE(test::lines_of(human.out).empty());
  EXPECT_EQ(test::lines_of(human.out)[0], "lambert  (1000 samples per chi2 test, seed 7)");
}

// tabulate refuses a BRDF that is negative anywhere above the horizon; --clamp-negative stores
// max(0, ρ) instead. Bagher's Fresnel F0 + (1 − F0)(1 − cosθd)⁵ − F1 cosθd with F0 = 0.3, F1 = 0.35
// is negative for θd below about 30° (F(0°) = −0.05) and positive beyond; kd = 0, so those cells
// are 0 in every channel and every other cell is the model's value (checked on every 53rd cell
// against the library's evaluation at the cell centre); the refusal and the JSON count the same cells.
TEST(CliTabulate, ClampNegativeStoresZeroWhereTheBrdfIsNegative) {
  const fs::path dir = test::scratch_dir("tabulate_clamp");
  const std::string model = "cook-torrance-sgd-bagher2012";
  const std::vector<std::string> params = {"kd=0", "ks=1", "F0=0.3", "F1=0.35"};
  std::string args = "tabulate " + model;
  for (const auto& p : params) args += " --param " + p;

  const auto refused = run_cli(args + " -o " + q(dir / "refused.binary"));
  EXPECT_EQ(refused.exit_code, 2);
  const std::string head = "brdfkit: model '" + model + "': the BRDF is negative in ";
  ASSERT_EQ(refused.err.rfind(head, 0), 0u) << refused.err;
  const size_t negative = std::stoul(refused.err.substr(head.size()));
  EXPECT_EQ(refused.err, head + std::to_string(negative) + " cells (they would read as 'not measured'); nothing written "
                                                           "(--clamp-negative stores max(0, rho) instead)\n");
  EXPECT_FALSE(fs::exists(dir / "refused.binary"));
  EXPECT_GT(negative, 100000u);

  const auto r = run_cli(args + " --clamp-negative --json -o " + q(dir / "clamped.binary"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(stdout_json(r)["cells_clamped"].get<size_t>(), negative);
  const merl::Table t = merl::read(dir / "clamped.binary");
  const Model& m = model_by_name(model);
  const Brdf b(m, fit::params_from_args(m.params(), params));
  size_t zero = 0, sampled = 0, sampled_negative = 0;
  for (size_t k = 0; k < merl::kCellCount; ++k) {
    Vec3d wi, wo;
    if (!merl::cell_directions(merl::cell_at(k), wi, wo)) continue;
    ASSERT_TRUE(t.valid(k)) << "cell " << k;
    const Rgb got = t.value(k);
    zero += (got.array() == 0).all();
    if (k % 53) continue;
    ++sampled;
    const Rgb want = b.eval(wi, wo);
    if ((want.array() < 0).any()) {
      ++sampled_negative;
      EXPECT_TRUE((got.array() == 0).all()) << "cell " << k << ": " << got.transpose();
    } else {  // the stored value, ρ/scale read back × scale, rounds only in the last bits
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-14 * want[c]) << "cell " << k;
    }
  }
  // Cells where the model is exactly 0 (D or G vanishing at grazing angles) are stored as 0 too;
  // the sample's share of negative cells is the count's share.
  const double share = double(negative) / double(t.valid_count()), sampled_share = double(sampled_negative) / double(sampled);
  std::printf("bagher F0 0.3, F1 0.35: %zu of %zu cells negative (%.4f), %zu stored as 0; of %zu sampled cells %zu "
              "negative (%.4f)\n",
              negative, t.valid_count(), share, zero, sampled, sampled_negative, sampled_share);
  EXPECT_GE(zero, negative);
  EXPECT_NEAR(sampled_share, share, 0.01);
  fs::remove_all(dir);
}

// analyze --what backscatter --space: the slice fit minimizes the error of its space, so each
// family's linear-space fit has the lower linear error and the log-space fit the lower log error,
// channel by channel (on the real pink-felt slice).
TEST(CliAnalyze, SpaceChoosesTheErrorTheSliceFitMinimizes) {
  BRDFKIT_REQUIRE_DATA("merl-slices");
  const std::string args =
      "analyze " + q(test::data_dir() / "merl-slices" / "pink-felt-1d.alta") + " --what backscatter --families beckmann,ggx --json";
  const auto lin = run_cli(args + " --space linear"), log = run_cli(args + " --space log");
  ASSERT_EQ(lin.exit_code, 0) << lin.err;
  ASSERT_EQ(log.exit_code, 0) << log.err;
  const auto a = stdout_json(lin), b = stdout_json(log);
  EXPECT_EQ(a["fit_space"], "linear");
  EXPECT_EQ(b["fit_space"], "log");
  ASSERT_EQ(a["fits"].size(), 2u);
  ASSERT_EQ(b["fits"].size(), 2u);
  for (size_t f = 0; f < 2; ++f) {
    const auto &fa = a["fits"][f], &fb = b["fits"][f];
    ASSERT_EQ(fa["family"], fb["family"]);
    for (size_t c = 0; c < 3; ++c) {
      const auto &ca = fa["channels"][c], &cb = fb["channels"][c];
      EXPECT_LE(ca["error_linear"].get<double>(), cb["error_linear"].get<double>() * (1 + 1e-9)) << fa["family"] << c;
      EXPECT_LE(cb["error_log"].get<double>(), ca["error_log"].get<double>() * (1 + 1e-9)) << fa["family"] << c;
    }
    std::printf("pink-felt %s: linear fit err_linear %.5f err_log %.5f; log fit err_linear %.5f err_log %.5f\n",
                fa["family"].get<std::string>().c_str(), fa["mean_error_linear"].get<double>(),
                fa["mean_error_log"].get<double>(), fb["mean_error_linear"].get<double>(), fb["mean_error_log"].get<double>());
    EXPECT_LT(fa["mean_error_linear"].get<double>(), fb["mean_error_linear"].get<double>());
    EXPECT_LT(fb["mean_error_log"].get<double>(), fa["mean_error_log"].get<double>());
  }
}

// --max-theta-h keeps the slice's angles up to the bound: 40° keeps fewer of them than the
// default 80°, none above.
TEST(CliAnalyze, MaxThetaHCutsTheSlice) {
  BRDFKIT_REQUIRE_DATA("merl-slices");
  const std::string args =
      "analyze " + q(test::data_dir() / "merl-slices" / "pink-felt-1d.alta") + " --what backscatter --families ggx --json";
  const auto all = stdout_json(run_cli(args)), cut = stdout_json(run_cli(args + " --max-theta-h 40"));
  EXPECT_EQ(all["max_theta_h_deg"].get<double>(), 80.0);
  EXPECT_EQ(cut["max_theta_h_deg"].get<double>(), 40.0);
  auto largest = [](const nlohmann::json& j) {
    double t = 0;
    for (const auto& s : j["slice"]) t = std::max(t, s["theta_h"].get<double>());
    return t * 180 / kPi;
  };
  std::printf("pink-felt slice: %zu angles up to %.2f deg; with --max-theta-h 40: %zu up to %.2f deg\n",
              all["slice"].size(), largest(all), cut["slice"].size(), largest(cut));
  EXPECT_LE(largest(cut), 40.0);
  EXPECT_GT(largest(all), 70.0);
  EXPECT_LT(cut["slice"].size(), all["slice"].size());
}

// analyze --what diffraction --threshold: a cell is diffraction-dominated in a channel exactly
// where |det| < threshold; the counts grow with the threshold and a huge one takes every
// classified cell (RGL satin_rosaline, 20 × 20 cells).
TEST(CliAnalyze, ThresholdClassifiesCellsByTheirDeterminant) {
  BRDFKIT_REQUIRE_DATA("rgl");
  const std::string args =
      "analyze " + q(test::data_dir() / "rgl" / "satin_rosaline_rgb.bsdf") + " --what diffraction --nodes 20 --json";
  std::array<int, 3> previous{-1, -1, -1};
  for (const double t : {0.01, 0.1, 1e9}) {
    const auto r = run_cli(args + " --threshold " + std::to_string(t));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = stdout_json(r);
    EXPECT_EQ(j["threshold"].get<double>(), t);
    for (size_t c = 0; c < 3; ++c) {
      int below = 0, flagged = 0;
      for (const auto& cell : j["cells"]) {
        if (cell["det"][c].is_number() && std::abs(cell["det"][c].get<double>()) < t) ++below;
        flagged += cell["diffraction"][c].get<bool>();
      }
      const int n = j["summary"][c]["diffraction_cells"].get<int>();
      EXPECT_EQ(n, below) << "threshold " << t << " channel " << c;
      EXPECT_EQ(n, flagged) << "threshold " << t << " channel " << c;
      EXPECT_GT(n, previous[c]) << "threshold " << t << " channel " << c;
      if (t > 1e8) {
        EXPECT_EQ(n, j["summary"][c]["classified"].get<int>()) << c;
      }
      previous[c] = n;
    }
    std::printf("satin_rosaline, threshold %g: diffraction-dominated cells R %d G %d B %d\n", t, previous[0],
                previous[1], previous[2]);
  }
}

// analyze --what ndf: --iterations bounds the masking iterations (one residual per iteration
// after the first estimate, and more of them lower it); --metric is the least squares the
// estimate solves, so its residuals are that metric's (each with the masking of the iteration
// before: within 15 % of the reported value, on scales 100× apart for ngan and low-e1); --report
// picks the metrics reported; --compare fits catalogue models under the same metric (the number
// `fit` gives).
TEST_F(CliOptions, AnalyzeNdfIterationsMetricReportAndCompare) {
  const std::string args = "analyze " + data() + " --what ndf --coarsen 8 --nodes 30 --f0 0.04 --report low-e1,ngan --json";
  const auto e1 = stdout_json(run_cli(args + " --metric low-e1 --iterations 1 --compare ward"));
  const auto e1_three = stdout_json(run_cli(args + " --metric low-e1 --iterations 3"));
  const auto ngan = stdout_json(run_cli(args + " --iterations 1"));
  EXPECT_EQ(e1["iterations"], 1);
  EXPECT_EQ(e1["grid_coarsen"], 8);
  EXPECT_FALSE(e1["f0_fitted"].get<bool>());  // --f0 given
  EXPECT_EQ(e1["parameters"]["F0"], nlohmann::json::array({0.04, 0.04, 0.04}));
  ASSERT_EQ(e1["residual_history"].size(), 2u);
  ASSERT_GE(e1_three["iterations"].get<int>(), 2);
  ASSERT_LE(e1_three["iterations"].get<int>(), 3);
  ASSERT_EQ(e1_three["residual_history"].size(), e1_three["iterations"].get<size_t>() + 1);
  const auto history = e1_three["residual_history"].get<std::vector<double>>();
  for (size_t k = 1; k < history.size(); ++k) EXPECT_LE(history[k], history[k - 1]) << k;
  const auto last = [](const nlohmann::json& j) { return j["residual_history"].back().get<double>(); };
  std::printf("ndf estimate: low-e1 residuals %.6g (1 iteration), %.6g (%d); reported low-e1 %.6g; ngan residual "
              "%.6g, reported ngan %.6g\n",
              last(e1), last(e1_three), e1_three["iterations"].get<int>(), e1["metrics"]["low-e1"].get<double>(),
              last(ngan), ngan["metrics"]["ngan"].get<double>());
  EXPECT_LT(last(e1_three), last(e1));
  EXPECT_NEAR(last(e1), e1["metrics"]["low-e1"].get<double>(), 0.15 * e1["metrics"]["low-e1"].get<double>());
  EXPECT_NEAR(last(ngan), ngan["metrics"]["ngan"].get<double>(), 0.15 * ngan["metrics"]["ngan"].get<double>());
  EXPECT_GT(last(ngan), 10 * last(e1));
  for (const auto* j : {&e1, &e1_three, &ngan}) {
    std::set<std::string> keys;
    for (const auto& [k, v] : (*j)["metrics"].items()) keys.insert(k);
    EXPECT_EQ(keys, (std::set<std::string>{"low-e1", "ngan"}));
  }
  EXPECT_FALSE(e1_three.contains("compare"));
  const auto fit = run_cli("fit " + data() + " --model ward --metric low-e1 --coarsen 8 --report low-e1 --json -o " +
                           q(path("ndf_ward.json")));
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  const double ward = stdout_json(fit)["metrics"]["low-e1"].get<double>();
  std::printf("ward under low-e1: analyze --compare %.9g, fit %.9g\n", e1["compare"]["ward"].get<double>(), ward);
  EXPECT_NEAR(e1["compare"]["ward"].get<double>(), ward, 1e-9 * ward);
}

// analyze --what fresnel --model: the Fresnel term is read off the model fitted here (the
// measurement divided by its other factors), so a different model gives a different curve and
// says which it is. --coarsen is the grid of that fit (stated), --starts its number of starts
// (more starts end elsewhere in the last digits).
TEST_F(CliOptions, AnalyzeFresnelUsesTheModelNamed) {
  const std::string args = "analyze " + data() + " --what fresnel --coarsen 8 --nodes 8 --json";
  const auto ggx = stdout_json(run_cli(args));
  const auto beck = stdout_json(run_cli(args + " --model cook-torrance-beckmann"));
  const auto more = stdout_json(run_cli(args + " --starts 4"));
  EXPECT_EQ(ggx["model"], "cook-torrance-ggx");
  EXPECT_EQ(beck["model"], "cook-torrance-beckmann");
  EXPECT_EQ(ggx["model_source"].get<std::string>().rfind("fitted here under ngan (grid coarsen 8): ngan = ", 0), 0u)
      << ggx["model_source"];
  ASSERT_EQ(ggx["rows"].size(), 8u);
  ASSERT_EQ(beck["rows"].size(), 8u);
  ASSERT_EQ(more["rows"].size(), 8u);
  double model = 0, starts = 0;
  for (size_t k = 0; k < 8; ++k)
    for (size_t c = 0; c < 3; ++c) {
      const double g = ggx["rows"][k]["model"][c].get<double>();
      model = std::max(model, std::abs(g - beck["rows"][k]["model"][c].get<double>()));
      starts = std::max(starts, std::abs(g - more["rows"][k]["model"][c].get<double>()));
    }
  std::printf("fresnel curve: Beckmann instead of GGX moves it by %.3g, 4 starts instead of 1 by %.3g\n", model, starts);
  EXPECT_GT(model, 1e-4);
  EXPECT_GT(starts, 0.0);
  EXPECT_LT(starts, 1e-5);
}

std::vector<double> all_values(const nlohmann::json& record) {
  std::vector<double> v;
  for (const auto& p : record["params"])
    for (const auto& x : p["values"]) v.push_back(x.get<double>());
  return v;
}

// fit --seed: the random starts (--starts 3) repeat bit for bit with one seed and differ with
// another (other solver runs: other iteration counts, or another best start and other last
// digits); the record keeps the seed.
// --verbose prints the procedure's steps on stderr, which is empty without it.
TEST_F(CliOptions, FitSeedRepeatsAndChangesTheStartsAndVerboseTalks) {
  const std::string args = "fit " + data() + " --model cook-torrance-ggx --coarsen 4 --starts 3 --report ngan";
  auto run = [&](int seed, const std::string& extra) {
    const fs::path out = path("seed" + std::to_string(seed) + "_" + std::to_string(extra.size()) + ".json");
    const auto r = run_cli(args + " --seed " + std::to_string(seed) + extra + " -o " + q(out));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return std::make_pair(r, read_json(out));
  };
  const auto [r1, a] = run(1, "");
  const auto [r1v, again] = run(1, " --verbose");
  const auto [r2, other] = run(2, "");
  EXPECT_EQ(a["fit"]["seed"], 1);
  EXPECT_EQ(other["fit"]["seed"], 2);
  EXPECT_EQ(all_values(a), all_values(again));
  EXPECT_EQ(a["fit"]["iterations"], again["fit"]["iterations"]);  // every start's, summed
  std::printf("cook-torrance-ggx, 3 starts: seed 1 best start %d, %d iterations; seed 2 best start %d, %d iterations; alpha "
              "%.12g vs %.12g\n",
              a["fit"]["best_start"].get<int>(), a["fit"]["iterations"].get<int>(), other["fit"]["best_start"].get<int>(),
              other["fit"]["iterations"].get<int>(), a["params"][2]["values"][0].get<double>(),
              other["params"][2]["values"][0].get<double>());
  // Other random starts: the solver runs differently even where the scanned start stays the best.
  EXPECT_TRUE(all_values(a) != all_values(other) || a["fit"]["iterations"] != other["fit"]["iterations"]);
  // The same fit either way: the starts only change where the solver stops.
  EXPECT_NEAR(a["metrics"]["ngan"].get<double>(), other["metrics"]["ngan"].get<double>(), 1e-6 * a["metrics"]["ngan"].get<double>());
  EXPECT_EQ(r1.err, "");
  EXPECT_EQ(r1v.err, "ngan: fitting cook-torrance-ggx under ngan\n");
}

// fit --threshold (hp-2step): the cells classified as diffraction-dominated are those with
// |det| below it, so the first step's counts grow with it and its line names it. fit-all
// --threshold reaches each fit the same way (here with 1 against fit's 0.3). --verbose streams
// the steps the record keeps; --max-iterations is the solver's limit, recorded.
TEST_F(CliOptions, FitThresholdSetsTheHpTwoStepClassification) {
  const std::string opts = " --procedure hp-2step --coarsen 20 --max-iterations 1 --report low-e1 --threshold ";
  const auto r = run_cli("fit " + data() + " --model holzschuch-pacanowski" + opts + "0.3 -v -o " + q(path("hp.json")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto batch = run_cli("fit-all " + data() + " --models holzschuch-pacanowski" + opts + "1 -o " + q(path("batch_hp")));
  ASSERT_EQ(batch.exit_code, 0) << batch.err;
  const auto low = read_json(path("hp.json"));
  const auto high = read_json(path("batch_hp") / "widths" / "holzschuch-pacanowski.json");
  const auto red = [&](const nlohmann::json& j, const std::string& t) {
    const std::string step = j["fit"]["steps"][0].get<std::string>();
    EXPECT_EQ(step.rfind("classified (θh, θd) cells with |det(∇ log ρ, ∇f)| < " + t + " (seed 004 Eq. 15): R ", 0), 0u)
        << step;
    const auto at = step.find(": R ");
    return at == std::string::npos ? -1 : std::stoi(step.substr(at + 4));
  };
  const int n03 = red(low, "0.3"), n1 = red(high, "1");
  std::printf("hp-2step on the table, red channel: %d cells below 0.3 (fit), %d below 1 (fit-all)\n", n03, n1);
  EXPECT_GT(n03, 0);
  EXPECT_GT(n1, n03);
  // Streamed as they run: the classification and step 1 (step 2's line comes with its result).
  const auto lines = test::lines_of(r.err);
  ASSERT_EQ(lines.size(), 2u) << r.err;
  for (size_t k = 0; k < 2; ++k) EXPECT_EQ(lines[k], low["fit"]["steps"][k].get<std::string>());
  for (const auto* j : {&low, &high}) {
    EXPECT_EQ((*j)["fit"]["max_iterations"], 1);
    EXPECT_FALSE((*j)["fit"]["converged"].get<bool>());
  }
}

// fit --for mitsuba3 --export-output: the export goes where it says (and its scene file beside
// it), not beside the fit, with the fitted values.
TEST_F(CliOptions, FitExportOutputNamesTheExportedFile) {
  fs::create_directories(path("export"));
  const auto r = run_cli("fit " + data() + " --for mitsuba3 --model mitsuba-roughconductor-ggx --coarsen 8 --report ngan -o " +
                         q(path("rc.json")) + " --export-output " + q(path("export") / "rc_bsdf.xml"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("export") / "rc_bsdf.xml"));
  EXPECT_TRUE(fs::exists(path("export") / "rc_bsdf_scene.xml"));
  EXPECT_FALSE(fs::exists(path("rc.xml")));
  EXPECT_TRUE(test::has_line(r.out, "exported   " + (path("export") / "rc_bsdf.xml").string())) << r.out;
  const auto fit = read_json(path("rc.json"));
  double alpha = -1;
  for (const auto& p : fit["params"])
    if (p["name"] == "alpha") alpha = p["values"][0].get<double>();
  std::ifstream in(path("export") / "rc_bsdf.xml");
  const std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string key = "<float name=\"alpha\" value=\"";
  const auto at = xml.find(key);
  ASSERT_NE(at, std::string::npos) << xml;
  EXPECT_NEAR(std::stod(xml.substr(at + key.size())), alpha, 1e-12 * alpha) << xml;
}

// fit-all --models all | single-lobe: the catalogue and its single-lobe part (models/model_sets.h),
// in catalogue order. On a table with no measured cell every fit fails at once with the reason,
// so the sets are listed without fitting anything (exit 1: failed fits).
TEST_F(CliOptions, FitAllModelSetsExpandToTheCatalogue) {
  for (const std::string set : {"all", "single-lobe"}) {
    const fs::path out = path("set_" + set);
    const auto r = run_cli("fit-all " + q(path("empty.binary")) + " --models " + set + " --json -o " + q(out));
    EXPECT_EQ(r.exit_code, 1) << r.err;
    std::vector<std::string> want;
    for (const Model* m : parse_model_set(set)) want.emplace_back(m->name());
    const auto j = stdout_json(r);
    EXPECT_EQ(j["models"].get<std::vector<std::string>>(), want) << set;
    EXPECT_EQ(j["failed"].get<size_t>(), want.size());
    for (const auto& row : j["rows"])
      EXPECT_NE(row["reason"].get<std::string>().find("no measured cell"), std::string::npos) << row;
    const auto lines = test::lines_of(r.err);
    ASSERT_FALSE(lines.empty());
    EXPECT_EQ(lines[0], "fit-all: 1 material(s) x " + std::to_string(want.size()) + " model(s) = " +
                            std::to_string(want.size()) + " fits, 1 at once, into " + out.string());
  }
  EXPECT_EQ(parse_model_set("all").size(), all_models().size());
  EXPECT_EQ(parse_model_set("single-lobe").size(), 24u);  // README: He and the 23 others
}

// models --names: fit-all's sets list as fit-all expands them, names and sets mix in the given
// order, each model once; --names and --json exclude each other.
TEST_F(CliOptions, ModelsNamesListsTheSetsAsFitAllExpandsThem) {
  for (const std::string set : {"all", "single-lobe", "renderer", "anisotropic"}) {
    const auto r = run_cli("models " + set + " --names");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::vector<std::string> want;
    for (const Model* m : parse_model_set(set)) want.emplace_back(m->name());
    EXPECT_EQ(test::lines_of(r.out), want) << set;
  }
  const auto mixed = run_cli("models he single-lobe lambert --names");
  ASSERT_EQ(mixed.exit_code, 0) << mixed.err;
  const std::vector<std::string> lines = test::lines_of(mixed.out);
  ASSERT_EQ(lines.size(), 25u);  // he, the 23 other single-lobe models, lambert
  EXPECT_EQ(lines.front(), "he");
  EXPECT_EQ(std::count(lines.begin(), lines.end(), "he"), 1);
  EXPECT_EQ(lines.back(), "lambert");
  EXPECT_EQ(run_cli("models --names --json").exit_code, 2);
}

// fit-all --per-channel-shape, --seed: each fit gets them, as `fit` does. The table's lobes have
// α = 0.1, 0.2, 0.4 per channel: one shared Ward width without the option, three increasing with
// it, bit for bit the values `fit` finds with the same options.
TEST_F(CliOptions, FitAllPassesSeedAndPerChannelShapeToEachFit) {
  const std::string opts = " --coarsen 4 --starts 3 --report ngan";
  auto batch = [&](const std::string& extra, const std::string& name) {
    const auto r = run_cli("fit-all " + data() + " --models ward" + opts + extra + " -o " + q(path(name)));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_json(path(name) / "widths" / "ward.json");
  };
  const auto shared = batch(" --seed 2", "batch_shared");
  const auto per = batch(" --seed 2 --per-channel-shape", "batch_per");
  const auto alpha = [](const nlohmann::json& j) { return j["params"][2]["values"].get<std::vector<double>>(); };
  std::printf("ward alpha, shared: %.5f %.5f %.5f; per channel: %.5f %.5f %.5f\n", alpha(shared)[0], alpha(shared)[1],
              alpha(shared)[2], alpha(per)[0], alpha(per)[1], alpha(per)[2]);
  EXPECT_FALSE(shared["fit"]["per_channel_shape"].get<bool>());
  EXPECT_TRUE(per["fit"]["per_channel_shape"].get<bool>());
  EXPECT_EQ(alpha(shared)[0], alpha(shared)[2]);
  EXPECT_LT(alpha(per)[0], alpha(per)[1]);
  EXPECT_LT(alpha(per)[1], alpha(per)[2]);
  EXPECT_EQ(per["fit"]["seed"], 2);
  const auto single = run_cli("fit " + data() + " --model ward" + opts + " --seed 2 --per-channel-shape -o " +
                              q(path("single_per.json")));
  ASSERT_EQ(single.exit_code, 0) << single.err;
  EXPECT_EQ(all_values(per), all_values(read_json(path("single_per.json"))));
  const auto seed3 = batch(" --seed 3 --per-channel-shape", "batch_per3");
  EXPECT_EQ(seed3["fit"]["seed"], 3);
  // Start 0 (the scan's) wins under either seed; the random starts 1 and 2 differ, and so do
  // the iterations they take.
  std::printf("iterations of the 3 starts: seed 2 %d, seed 3 %d\n", per["fit"]["iterations"].get<int>(),
              seed3["fit"]["iterations"].get<int>());
  EXPECT_NE(per["fit"]["iterations"], seed3["fit"]["iterations"]);
}

fs::path envmap() { return test::data_dir() / "envmaps" / "studio.exr"; }

// render --env-intensity scales the map's radiance: the image doubles, pixel by pixel (the
// sampling distribution does not change). --env-rotation turns the map: a full turn is the same
// image, a quarter turn another one; the JSON states both.
TEST_F(CliOptions, RenderEnvIntensityAndRotation) {
  BRDFKIT_REQUIRE_DATA("envmaps");
  auto render = [&](const std::string& extra, const std::string& name) {
    const auto r = run_cli("render --model lambert --param kd=0.5 --env " + q(envmap()) +
                           " --size 8 --spp 4 -q" + extra + " -o " + q(path(name + ".png")));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return render::read_hdr_image(path(name + ".exr"));
  };
  const auto base = render("", "env_base"), twice = render(" --env-intensity 2", "env_twice");
  const auto full = render(" --env-rotation 360", "env_full"), quarter = render(" --env-rotation 90", "env_quarter");
  double lit = 0, worst = 0;
  for (size_t k = 0; k < base.size(); ++k)
    for (int c = 0; c < 3; ++c) {
      lit = std::max(lit, double(base.pixels[k][c]));
      worst = std::max(worst, std::abs(twice.pixels[k][c] - 2 * base.pixels[k][c]));
    }
  ASSERT_GT(lit, 0.01);
  EXPECT_LE(worst, 1e-6 * lit);
  const double turn = max_relative_difference(base, full), quarter_turn = max_relative_difference(base, quarter, 1e-3);
  std::printf("env map: intensity x2 off by %.3g; rotation 360 deg differs by %.3g, 90 deg by %.3g (relative)\n",
              worst, turn, quarter_turn);
  EXPECT_LT(turn, 1e-4);
  EXPECT_GT(quarter_turn, 0.05);
  EXPECT_EQ(read_json(path("env_twice.json"))["scene"], "environment " + envmap().string() + " (rotated 0 deg, x2)");
  EXPECT_EQ(read_json(path("env_quarter.json"))["scene"], "environment " + envmap().string() + " (rotated 90 deg, x1)");
}

// sRGB transfer function (IEC 61966-2-1), written out here to check the PNG independently.
double srgb(double x) { return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055; }

// render --seed: the same seed repeats the image bit for bit, another changes the noise.
// --exposure: the PNG is the EXR times 2^EV, clamped, sRGB-encoded, to the 8-bit step.
// --quiet: no progress lines on stderr (there are some without it).
TEST_F(CliOptions, RenderSeedExposureAndQuiet) {
  auto render = [&](const std::string& extra, const std::string& name) {
    const auto r = run_cli("render --model cook-torrance-ggx --param alpha=0.3 --env-constant 1 --light 30,45,2 "
                           "--size 8 --spp 2" + extra + " -o " + q(path(name + ".png")));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r;
  };
  const auto loud = render(" --seed 5 --exposure 1", "seed5");
  const auto quiet = render(" --seed 5 -q", "seed5_again");
  render(" --seed 6 -q", "seed6");
  EXPECT_EQ(quiet.err, "");
  EXPECT_TRUE(test::line_starting(loud.err, "render: cook-torrance-ggx ")) << loud.err;
  const auto a = render::read_hdr_image(path("seed5.exr")), b = render::read_hdr_image(path("seed5_again.exr"));
  const auto c = render::read_hdr_image(path("seed6.exr"));
  EXPECT_EQ(max_relative_difference(a, b), 0.0);
  EXPECT_GT(max_relative_difference(a, c), 1e-3);
  EXPECT_EQ(read_json(path("seed6.json"))["seed"], 6);
  EXPECT_EQ(read_json(path("seed6.json"))["spp"], 2);

  const auto j = read_json(path("seed5.json"));
  EXPECT_EQ(j["exposure_ev"].get<double>(), 1.0);
  const render::Rgb8Image png = render::read_png(path("seed5.png"));
  ASSERT_GE(png.width, a.width);
  int compared = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      if (!(a.at(x, y).maxCoeff() > 0)) continue;  // the background is drawn grey in the PNG only
      ++compared;
      for (int ch = 0; ch < 3; ++ch) {
        const double want = 255 * srgb(std::clamp(2.0 * a.at(x, y)[ch], 0.0, 1.0));
        EXPECT_NEAR(png.rgb[3 * (size_t(y) * size_t(png.width) + size_t(x)) + size_t(ch)], want, 0.51) << x << "," << y;
      }
    }
  EXPECT_GT(compared, 20);
}

// render --proxy: which sampler draws directions for the measured data. The fit's column is the
// same image either way; the measured column changes, and with the fit's sampler (auto) it is
// less noisy, so closer to the fit of the same lobes than with cosine sampling.
TEST_F(CliOptions, RenderProxyOnlyChangesTheMeasuredColumn) {
  const auto f = run_cli("fit " + data() + " --model cook-torrance-ggx --per-channel-shape --coarsen 8 --report ngan -o " +
                         q(path("proxy_fit.json")));
  ASSERT_EQ(f.exit_code, 0) << f.err;
  auto render = [&](const std::string& proxy) {
    const auto r = run_cli("render " + data() + " " + q(path("proxy_fit.json")) + " --proxy " + proxy +
                           " --env-constant 1 --size 16 --spp 8 -q -o " + q(path("proxy_" + proxy + ".png")));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return std::make_pair(render::read_hdr_image(path("proxy_" + proxy + ".exr")),
                          read_json(path("proxy_" + proxy + ".json"))["columns"][1]["image_rmse"].get<double>());
  };
  const auto [img_auto, rmse_auto] = render("auto");
  const auto [img_cos, rmse_cos] = render("cosine");
  ASSERT_EQ(img_auto.width, 32);
  double measured = 0, fitted = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 32; ++x) {
      const double d = (img_auto.at(x, y) - img_cos.at(x, y)).cwiseAbs().maxCoeff();
      (x < 16 ? measured : fitted) = std::max(x < 16 ? measured : fitted, d);
    }
  std::printf("proxy: measured column differs by %.3g, fit column by %.3g; image RMSE auto %.4g, cosine %.4g\n",
              measured, fitted, rmse_auto, rmse_cos);
  EXPECT_EQ(fitted, 0.0);
  EXPECT_GT(measured, 1e-3);
  EXPECT_LT(rmse_auto, rmse_cos);
}

// render --params FILE --material NAME renders that material's published fit: the same image as
// the same model and values saved as a fit record (Bagher's fits have one lobe shape per
// channel, which --param cannot give), and not the image of another material.
TEST_F(CliOptions, RenderParamsAndMaterialRenderThePublishedFit) {
  BRDFKIT_REQUIRE_DATA("published-fits");
  const fs::path file = test::data_dir() / "published-fits" / "bagher2012-sgd.json";
  const Brdf b = PublishedFits::read(file).brdf("pink-felt");
  fit::FitRecord rec;
  rec.model = std::string(b.model().name());
  rec.values = b.values();
  rec.per_channel_shape = true;
  fit::save_fit_record(path("pink-felt.json"), rec);
  const std::string common = " --env-constant 1 --light 30,45,2 --size 8 --spp 2 -q -o ";
  const auto a = run_cli("render --params " + q(file) + " --material pink-felt" + common + q(path("pub.png")));
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const auto m = run_cli("render --params " + q(path("pink-felt.json")) + common + q(path("pub_record.png")));
  ASSERT_EQ(m.exit_code, 0) << m.err;
  const auto other = run_cli("render --params " + q(file) + " --material alum-bronze" + common + q(path("pub_other.png")));
  ASSERT_EQ(other.exit_code, 0) << other.err;
  const auto img = render::read_hdr_image(path("pub.exr"));
  EXPECT_EQ(max_relative_difference(img, render::read_hdr_image(path("pub_record.exr"))), 0.0);
  EXPECT_GT(max_relative_difference(img, render::read_hdr_image(path("pub_other.exr")), 1e-3), 0.05);
}

// report: -o puts the site where it says (default RESULTS_DIR/report); --fits is how many fits
// each material page renders and plots; --seed, --size and --spp reach its renders (the render
// JSON states them); --env lights them with a map (the JSON names it) and --env-rotation turns it
// (the image changes); --quiet silences the progress lines.
TEST_F(CliOptions, ReportOptionsReachThePagesAndRenders) {
  const auto fit = run_cli("fit-all " + data() + " --models lambert,ward --coarsen 8 --report ngan -o " + q(path("res")));
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  const bool map = fs::exists(envmap());
  if (!map) std::printf("--env and --env-rotation not checked: %s is absent\n", envmap().string().c_str());
  const std::string env = map ? " --env " + q(envmap()) : "";
  auto report = [&](const std::string& extra) {
    const auto r = run_cli("report " + q(path("res")) + " --size 8 --spp 1" + extra);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r;
  };
  const auto a = report(" --fits 1 --seed 1 -q -o " + q(path("site_a")));
  const auto b = report(" --fits 2 --seed 2" + env);
  EXPECT_TRUE(test::has_line(a.out, (path("site_a") / "index.html").string())) << a.out;
  EXPECT_EQ(a.err, "");
  EXPECT_TRUE(test::has_line(b.out, (path("res") / "report" / "index.html").string())) << b.out;
  EXPECT_TRUE(test::line_starting(b.err, "report: ")) << b.err;
  const auto page = [&](const fs::path& site) { return read_json(site / "materials" / "widths.json"); };
  const auto pa = page(path("site_a")), pb = page(path("res") / "report");
  EXPECT_EQ(pa["fits"].size(), 2u);  // every fit is listed; --fits limits renders and plots
  EXPECT_EQ(pa["render"]["columns"].size(), 2u);  // measured + the best fit
  EXPECT_EQ(pb["render"]["columns"].size(), 3u);
  EXPECT_EQ(pa["plots"]["albedo"]["fits"].size(), 1u);
  EXPECT_EQ(pb["plots"]["albedo"]["fits"].size(), 2u);
  EXPECT_EQ(pa["render"]["width"], 8);
  EXPECT_EQ(pa["render"]["spp"], 1);
  EXPECT_EQ(pa["render"]["seed"], 1);
  EXPECT_EQ(pb["render"]["seed"], 2);
  EXPECT_EQ(pa["render"]["scene"].get<std::string>().rfind("built-in:", 0), 0u);
  if (!map) return;
  EXPECT_EQ(pb["render"]["scene"], "environment " + envmap().filename().string());
  report(" --fits 2 --seed 2 -q" + env + " --env-rotation 90 -o " + q(path("site_e")));
  const auto exr = [&](const fs::path& site) {
    return render::read_hdr_image(site / "materials" / "widths" / "render.exr");
  };
  const double turned = max_relative_difference(exr(path("res") / "report"), exr(path("site_e")), 1e-3);
  std::printf("report renders: the map turned 90 deg changes them by %.3g (relative)\n", turned);
  EXPECT_GT(turned, 0.05);
}

// export --json prints what was written: the files, the model, whether it was refitted, the
// added error and the fit's own error; the file is the same as without --json.
TEST_F(CliOptions, ExportJsonDescribesTheFilesWritten) {
  const auto f = run_cli("fit " + data() + " --model lambert --coarsen 8 --report ngan -o " + q(path("lambert.json")));
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const auto human = run_cli("export " + q(path("lambert.json")) + " --to glsl -o " + q(path("human.glsl")));
  const auto r = run_cli("export " + q(path("lambert.json")) + " --to glsl -o " + q(path("json.glsl")) + " --json");
  ASSERT_EQ(human.exit_code, 0) << human.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(test::has_line(human.out, "wrote      " + path("human.glsl").string())) << human.out;
  const auto j = stdout_json(r);
  EXPECT_EQ(j["files"], nlohmann::json::array({path("json.glsl").string()}));
  EXPECT_EQ(j["target"], "glsl");
  EXPECT_EQ(j["model"], "lambert");
  EXPECT_FALSE(j["refitted"].get<bool>());
  EXPECT_EQ(j["added_error"].get<double>(), 0.0);
  EXPECT_EQ(j["source_error"].get<double>(), read_json(path("lambert.json"))["metrics"]["ngan"].get<double>());
  std::ifstream x(path("human.glsl")), y(path("json.glsl"));
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(x), {}), std::string(std::istreambuf_iterator<char>(y), {}));
}

}  // namespace
}  // namespace brdfkit
