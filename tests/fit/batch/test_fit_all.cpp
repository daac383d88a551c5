// `brdfkit fit-all`: saved fits + summary CSV + table on small self-tabulated MERL materials,
// resuming (a rerun refits nothing; a damaged result is refitted), a run killed with SIGKILL then
// resumed (no corrupt or duplicated result), a failed fit among good ones, --jobs 1 vs 2,
// --compare against a published fit, and the model sets. Grids coarsened 4× to stay fast
// (DESIGN.md §7 allows coarse grids for tests only).
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/merl.h"
#include "brdfkit/models/published_fits.h"
#include "support/fit_test_util.h"
#include "support/test_util.h"

namespace brdfkit::test {
namespace {

namespace fs = std::filesystem;

// The CSV as rows of fields (no field of these tests holds a quoted comma except `reason`).
std::vector<std::map<std::string, std::string>> read_csv(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
  auto split = [](const std::string& s) {
    std::vector<std::string> out;
    std::string cur;
    bool quoted = false;
    for (size_t i = 0; i < s.size(); ++i) {
      const char c = s[i];
      if (quoted) {
        if (c == '"' && i + 1 < s.size() && s[i + 1] == '"') cur += '"', ++i;
        else if (c == '"') quoted = false;
        else cur += c;
      } else if (c == '"') {
        quoted = true;
      } else if (c == ',') {
        out.push_back(cur), cur.clear();
      } else {
        cur += c;
      }
    }
    out.push_back(cur);
    return out;
  };
  if (!std::getline(in, line)) return rows;
  header = split(line);
  while (std::getline(in, line)) {
    const auto f = split(line);
    EXPECT_EQ(f.size(), header.size()) << line;
    std::map<std::string, std::string> row;
    for (size_t i = 0; i < header.size() && i < f.size(); ++i) row[header[i]] = f[i];
    rows.push_back(row);
  }
  return rows;
}

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);  // throws on a corrupt file: the test fails
}

// Every parameter value of every JSON under `dir` (material/model → values), for comparisons.
std::map<std::string, nlohmann::json> all_params(const fs::path& dir) {
  std::map<std::string, nlohmann::json> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().extension() == ".json")
      out[fs::relative(e.path(), dir).string()] = read_json(e.path())["params"];
  return out;
}

class FitAll : public ::testing::Test {
 protected:
  // Three materials, Ward lobes of known widths: enough for a batch, small enough (coarsen 4) to be quick.
  static void SetUpTestSuite() {
    dir_ = new fs::path(scratch_dir("fit_all"));
    fs::create_directories(*dir_ / "data");
    const Model& ward = model_by_name("ward");
    const double alphas[] = {0.08, 0.15, 0.3};
    const char* names[] = {"matte-red", "satin-green", "shiny-blue"};
    for (int i = 0; i < 3; ++i)
      merl::write(*dir_ / "data" / (std::string(names[i]) + ".binary"),
                  tabulate_model(ward, make_values(ward, {{"kd", Rgb(0.3, 0.2, 0.1)},
                                                          {"ks", Rgb(0.05, 0.08, 0.1)},
                                                          {"alpha", Rgb::Constant(alphas[i])}})));
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  static std::string data() { return (*dir_ / "data").string(); }
  static std::string out(const std::string& name) { return (*dir_ / name).string(); }
  static std::string batch(const std::string& inputs, const std::string& outdir, const std::string& extra = "") {
    return "fit-all " + inputs + " --models lambert,ward --coarsen 4 --report ngan -o " + outdir + " " + extra;
  }
  static fs::path* dir_;
};
fs::path* FitAll::dir_ = nullptr;

TEST_F(FitAll, SavesEveryFitSummarizesAndResumesWithoutRefitting) {
  const std::string o = out("run1");
  const auto r = run_cli(batch(data(), o));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // One JSON per fit, recovering the tabulated widths; the CSV has one row per fit in a stable order.
  const auto rows = read_csv(fs::path(o) / "summary.csv");
  ASSERT_EQ(rows.size(), 6u);
  const char* expected[][2] = {{"matte-red", "lambert"},   {"matte-red", "ward"},  {"satin-green", "lambert"},
                               {"satin-green", "ward"},    {"shiny-blue", "lambert"}, {"shiny-blue", "ward"}};
  const double alphas[] = {0.08, 0.15, 0.3};
  for (size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(rows[i].at("material"), expected[i][0]);
    EXPECT_EQ(rows[i].at("model"), expected[i][1]);
    EXPECT_EQ(rows[i].at("status"), "fitted");
    EXPECT_EQ(rows[i].at("fit_metric"), "ngan");
    EXPECT_FALSE(rows[i].at("ngan").empty());
    const auto j = read_json(fs::path(o) / expected[i][0] / (std::string(expected[i][1]) + ".json"));
    EXPECT_EQ(j["data"]["material"], expected[i][0]);
    EXPECT_TRUE(j["fit"]["procedure"].is_null());
    EXPECT_EQ(j["fit"]["metric"], "ngan");
    if (std::string(expected[i][1]) == "ward") {
      const double alpha = j["params"][2]["values"][0];
      EXPECT_NEAR(alpha, alphas[i / 2], 0.05 * alphas[i / 2]) << expected[i][0];
      // The Ward fit of Ward data beats the Lambertian one by far.
      EXPECT_LT(std::stod(rows[i].at("ngan")), 0.2 * std::stod(rows[i - 1].at("ngan")));
    }
  }
  // The table: every model and material, the fitting metric's values.
  EXPECT_NE(r.out.find("ngan error of each fit"), std::string::npos) << r.out;
  for (const char* s : {"lambert", "ward", "matte-red", "satin-green", "shiny-blue"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s << "\n" << r.out;
  EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("[6/6]"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("6 fitted, 0 skipped"), std::string::npos) << r.err;

  // A rerun refits nothing: the files are untouched and the same numbers are reported.
  std::map<fs::path, fs::file_time_type> mtimes;
  for (const auto& e : fs::recursive_directory_iterator(o))
    if (e.path().extension() == ".json") mtimes[e.path()] = fs::last_write_time(e.path());
  ASSERT_EQ(mtimes.size(), 6u);
  const auto again = run_cli(batch(data(), o));
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.err.find("0 fitted, 6 skipped"), std::string::npos) << again.err;
  for (const auto& [p, t] : mtimes) EXPECT_EQ(fs::last_write_time(p), t) << p;
  const auto rows2 = read_csv(fs::path(o) / "summary.csv");
  ASSERT_EQ(rows2.size(), 6u);
  for (size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(rows2[i].at("status"), "resumed");
    EXPECT_EQ(rows2[i].at("ngan"), rows[i].at("ngan"));
  }
  EXPECT_EQ(again.out, r.out);

  // A damaged result and a result made under other options are refitted; the others are kept.
  std::ofstream(fs::path(o) / "satin-green" / "ward.json", std::ios::trunc) << "{\"format\": \"brdfkit-fit\", ";
  const auto third = run_cli(batch(data(), o));
  ASSERT_EQ(third.exit_code, 0) << third.err;
  EXPECT_NE(third.err.find("1 fitted, 5 skipped"), std::string::npos) << third.err;
  const auto other = run_cli(batch(data(), o, "--max-iterations 50"));
  ASSERT_EQ(other.exit_code, 0) << other.err;
  EXPECT_NE(other.err.find("6 fitted, 0 skipped"), std::string::npos) << other.err;
}

TEST_F(FitAll, KilledMidRunThenRerunLeavesExactlyOneValidResultPerFit) {
  const std::string o = out("killed");
  const fs::path first = fs::path(o) / "matte-red" / "lambert.json";
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string devnull = "/dev/null";
    std::freopen(devnull.c_str(), "w", stdout);
    std::freopen(devnull.c_str(), "w", stderr);
    ::execl(BRDFKIT_CLI_PATH, BRDFKIT_CLI_PATH, "fit-all", data().c_str(), "--models", "lambert,ward,blinn-phong",
            "--starts", "2", "--coarsen", "4", "--report", "ngan", "-o", o.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Kill as soon as the first result lands: the others are in flight or not started.
  int status = 0;
  bool exited = false;
  const auto t0 = std::chrono::steady_clock::now();
  while (!fs::exists(first) && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(120)) {
    if (::waitpid(pid, &status, WNOHANG) == pid) {
      exited = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (!exited) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
  }
  ASSERT_TRUE(fs::exists(first));
  size_t saved_before = 0;
  for (const auto& e : fs::recursive_directory_iterator(o))
    if (e.path().extension() == ".json") ++saved_before;
  EXPECT_LT(saved_before, 9u) << "the run finished before it could be killed";
  std::cout << "killed after " << saved_before << " of 9 fits had been saved\n";

  const auto r = run_cli("fit-all " + data() + " --models lambert,ward,blinn-phong --starts 2 --coarsen 4 "
                         "--report ngan -o " + o);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find(std::to_string(saved_before) + " skipped"), std::string::npos) << r.err;
  // Exactly one parseable JSON per fit, no temporaries left, one CSV row per fit.
  std::set<std::string> jsons;
  for (const auto& e : fs::recursive_directory_iterator(o)) {
    if (!e.is_regular_file()) continue;
    const std::string name = e.path().filename().string();
    EXPECT_EQ(name.find(".tmp."), std::string::npos) << e.path();
    if (e.path().extension() == ".json") {
      EXPECT_NO_THROW(read_json(e.path())) << e.path();
      jsons.insert(fs::relative(e.path(), o).string());
    }
  }
  EXPECT_EQ(jsons.size(), 9u);
  const auto rows = read_csv(fs::path(o) / "summary.csv");
  ASSERT_EQ(rows.size(), 9u);
  std::set<std::pair<std::string, std::string>> pairs;
  for (const auto& row : rows) {
    pairs.insert({row.at("material"), row.at("model")});
    EXPECT_NE(row.at("status"), "failed") << row.at("reason");
  }
  EXPECT_EQ(pairs.size(), 9u);
}

TEST_F(FitAll, AFailedFitIsReportedWithItsReasonAndTheOthersComplete) {
  const fs::path mixed = *dir_ / "mixed";
  fs::create_directories(mixed);
  fs::copy_file(fs::path(data()) / "matte-red.binary", mixed / "good.binary", fs::copy_options::overwrite_existing);
  std::ofstream(mixed / "broken.binary") << "not a MERL table";
  const std::string o = out("mixed_out");
  const auto r = run_cli(batch(mixed.string(), o));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const auto rows = read_csv(fs::path(o) / "summary.csv");
  ASSERT_EQ(rows.size(), 4u);
  for (const auto& row : rows) {
    if (row.at("material") == "broken") {
      EXPECT_EQ(row.at("status"), "failed");
      EXPECT_NE(row.at("reason").find("broken.binary"), std::string::npos) << row.at("reason");
      EXPECT_TRUE(row.at("ngan").empty());
    } else {
      EXPECT_EQ(row.at("status"), "fitted") << row.at("reason");
      EXPECT_FALSE(row.at("ngan").empty());
    }
  }
  EXPECT_NE(r.out.find("failed fits:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("broken / ward: "), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("FAILED"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(fs::path(o) / "broken" / "ward.json"));
  EXPECT_TRUE(fs::exists(fs::path(o) / "good" / "ward.json"));
}

TEST_F(FitAll, OneAndTwoJobsGiveIdenticalParameters) {
  const auto one = run_cli(batch(data(), out("jobs1"), "--jobs 1"));
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const auto two = run_cli(batch(data(), out("jobs2"), "--jobs 2"));
  ASSERT_EQ(two.exit_code, 0) << two.err;
  const auto a = all_params(out("jobs1")), b = all_params(out("jobs2"));
  ASSERT_EQ(a.size(), 6u);
  EXPECT_EQ(a, b);
  EXPECT_EQ(one.out, two.out);  // the table too
}

TEST_F(FitAll, CompareShowsThePublishedFitsErrorUnderTheSameMetric) {
  BRDFKIT_REQUIRE_DATA("published-fits");
  const fs::path pub = data_dir() / "published-fits" / "low2012-cooktorrance-E2.json";
  // A material named like a MERL one, tabulated from that published fit, next to one the file lacks.
  const fs::path dir = *dir_ / "merl_named";
  fs::create_directories(dir);
  const Brdf b = PublishedFits::read(pub).brdf("alum-bronze");
  merl::write(dir / "alum-bronze.binary", merl::tabulate([&](const Vec3d& wi, const Vec3d& wo) { return b.eval(wi, wo); }));
  fs::copy_file(fs::path(data()) / "matte-red.binary", dir / "matte-red.binary", fs::copy_options::overwrite_existing);
  const std::string o = out("compare");
  const auto r = run_cli(batch(dir.string(), o, "--compare " + pub.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = read_csv(fs::path(o) / "summary.csv");
  ASSERT_EQ(rows.size(), 4u);
  const auto e = run_cli("error " + (dir / "alum-bronze.binary").string() + " --params " + pub.string() +
                         " --material alum-bronze --metric ngan --coarsen 4 --json");
  ASSERT_EQ(e.exit_code, 0) << e.err;
  const double published = nlohmann::json::parse(e.out)["metrics"]["ngan"];
  for (const auto& row : rows) {
    if (row.at("material") == "alum-bronze") {
      ASSERT_FALSE(row.at("published_ngan").empty());
      EXPECT_EQ(std::stod(row.at("published_ngan")), published);
      // Its own tabulation: the published fit's error is the look-up's quantization only, below
      // what a Lambertian fit reaches.
      if (row.at("model") == "lambert") {
        EXPECT_LT(published, 0.5 * std::stod(row.at("ngan")));
      }
    } else {
      EXPECT_TRUE(row.at("published_ngan").empty());
    }
  }
  EXPECT_NE(r.out.find("published"), std::string::npos) << r.out;
}

TEST_F(FitAll, FitWithAProcedureSavesItAndErrorReproducesIt) {
  const std::string in = (fs::path(data()) / "satin-green.binary").string(), o = out("proc.json");
  const auto fit = run_cli("fit " + in + " --model ward --procedure low-e1 --coarsen 4 --report low-e1,ngan -o " + o);
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  const auto saved = read_json(o);
  EXPECT_EQ(saved["fit"]["procedure"], "low-e1");
  EXPECT_EQ(saved["fit"]["metric"], "low-e1");
  EXPECT_FALSE(saved["fit"]["steps"].empty());
  const auto err = run_cli("error " + in + " --params " + o + " --metric low-e1,ngan --json");
  ASSERT_EQ(err.exit_code, 0) << err.err;
  const auto recomputed = nlohmann::json::parse(err.out);
  for (const char* id : {"low-e1", "ngan"}) EXPECT_EQ(saved["metrics"][id], recomputed["metrics"][id]) << id;
  const double alpha = saved["params"][2]["values"][0];
  EXPECT_NEAR(alpha, 0.15, 0.15 * 0.05);
}

// Every fitted value lies in its search box: the model's by default, the user's with --bounds
// (here a box for Ward's α that excludes the truths 0.08–0.3, so the fit ends on its edge).
TEST_F(FitAll, EveryFittedValueStaysInsideItsSearchBoxAndBoundsReplaceTheBox) {
  const auto inside = [](const fs::path& dir, const std::map<std::string, std::pair<double, double>>& user) {
    int checked = 0;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
      if (e.path().extension() != ".json" || e.path().filename() == "summary.json") continue;
      const nlohmann::json j = read_json(e.path());
      if (!j.contains("params")) continue;
      const ParamTable& table = model_by_name(j["model"].get<std::string>()).params();
      for (const auto& p : j["params"]) {
        const ParamSpec& s = table[size_t(find_param(table, p["name"].get<std::string>()))];
        const auto box = user.contains(s.name) ? user.at(s.name) : std::pair{s.lower, s.upper};
        for (double v : p["values"].get<std::vector<double>>()) {
          EXPECT_GE(v, box.first) << e.path() << " " << s.name;
          EXPECT_LE(v, box.second) << e.path() << " " << s.name;
          ++checked;
        }
      }
    }
    return checked;
  };
  const std::string models = " --models lambert,ward,blinn-phong,cook-torrance-ggx --coarsen 4 --report ngan -o ";
  ASSERT_EQ(run_cli("fit-all " + data() + models + out("boxed")).exit_code, 0);
  EXPECT_EQ(inside(out("boxed"), {}), 3 * (3 + 9 + 9 + 12));

  const auto r = run_cli("fit-all " + data() + models + out("user_box") + " --bounds alpha=0.4:0.6");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(inside(out("user_box"), {{"alpha", {0.4, 0.6}}}), 3 * (3 + 9 + 9 + 12));
  const nlohmann::json ward = read_json(out("user_box") + "/shiny-blue/ward.json");
  EXPECT_DOUBLE_EQ(ward["params"][2]["values"][0].get<double>(), 0.4);  // truth 0.3: the box's edge
  EXPECT_EQ(ward["fit"]["bounds"]["alpha"], nlohmann::json::array({0.4, 0.6}));
}

TEST_F(FitAll, BadOptionsExitWithTwoAndNameTheProblem) {
  const std::pair<std::string, std::string> cases[] = {
      {"fit-all " + data() + " --models no-such-model -o " + out("bad"), "no-such-model"},
      {"fit-all " + data() + " --models ward --procedure no-such -o " + out("bad"), "no-such"},
      {"fit-all " + data() + " --models ward --metric rmse -o " + out("bad"), "rmse"},
      {"fit-all " + data() + " --models ward --jobs 0 -o " + out("bad"), "--jobs"},
      {"fit-all " + data() + " --models ward --procedure ngan --metric ngan -o " + out("bad"), "excludes"},
      {"fit-all " + out("empty_dir_absent") + "/ --models ward -o " + out("bad"), "no measured file"},
      {"fit-all " + data() + " --models ward --compare " + out("none.json") + " -o " + out("bad"), "none.json"},
      {"fit " + data() + "/matte-red.binary --model ward --procedure ngan --metric ngan -o " + out("x.json"), "excludes"},
      {"fit-all " + data() + " --models ward --bounds nope=0:1 -o " + out("bad"), "parameter 'nope'"},
      {"fit " + data() + "/matte-red.binary --model ward --bounds alpha=0.2:0.1 -o " + out("x.json"), "--bounds"},
      {"fit " + data() + "/matte-red.binary --model ward --bounds alpha=0:0.5 -o " + out("x.json"), "domain"},
      {"fit " + data() + "/matte-red.binary --model ward --bounds alpha=0.1 -o " + out("x.json"), "NAME=LOWER:UPPER"},
  };
  fs::create_directories(out("empty_dir_absent"));
  for (const auto& [args, needle] : cases) {
    const auto r = run_cli(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << args << "\n" << r.err;
    if (args.starts_with("fit-all")) {  // every option is checked before the batch is announced
      EXPECT_EQ(r.err.find("fits,"), std::string::npos) << args << ": rejected after announcing the batch: " << r.err;
    }
  }
}

}  // namespace
}  // namespace brdfkit::test
