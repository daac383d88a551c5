// `fit-all` under concurrency, kills, a full disk and Ctrl-C (the claim protocol of
// fit/batch/fit_batch.h): claims exclude each other and die with their process; a fit claimed
// elsewhere is listed as running elsewhere; two concurrent batches fit each pair once; one of
// them killed with SIGKILL then a rerun leaves exactly one valid result per fit; a file size
// limit (the full disk of a test) stops with one line naming the file and no partial file;
// SIGINT keeps every finished fit, writes the summary and exits 130. Inputs: small MERL tables
// tabulated here from Ward lobes, grids coarsened 4× (DESIGN.md §7) so a fit takes ~1 s or less.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "brdfkit/fit/batch/fit_claim.h"
#include "brdfkit/measured/merl.h"
#include "support/fit_test_util.h"
#include "support/test_util.h"

namespace brdfkit::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// A CLI process started with fork/exec, its stdout and stderr in files.
struct Child {
  pid_t pid = -1;
  fs::path out, err;
};

// Starts the CLI with `args`. fsize_limit > 0 caps every file it writes (RLIMIT_FSIZE) with
// SIGXFSZ ignored, so write(2) fails with EFBIG there, as it fails with ENOSPC on a full disk.
Child spawn(const std::vector<std::string>& args, const fs::path& logs, const std::string& tag, rlim_t fsize_limit = 0) {
  Child c{-1, logs / (tag + ".out"), logs / (tag + ".err")};
  std::vector<std::string> argv_s{BRDFKIT_CLI_PATH};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  c.pid = ::fork();
  if (c.pid == 0) {  // only async-signal-safe calls until exec
    const int out = ::open(c.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(c.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0 || ::dup2(out, 1) < 0 || ::dup2(err, 2) < 0) ::_exit(126);
    if (fsize_limit > 0) {
      ::signal(SIGXFSZ, SIG_IGN);
      const rlimit lim{fsize_limit, fsize_limit};
      if (::setrlimit(RLIMIT_FSIZE, &lim) != 0) ::_exit(126);
    }
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return c;
}

// The exit code, or 128 + the signal that ended it (as a shell reports it).
int wait_exit(pid_t pid) {
  int status = 0;
  if (::waitpid(pid, &status, 0) != pid) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::string slurp(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Waits up to `limit` for `ready`; false when it never came.
bool wait_for(const std::function<bool()>& ready, std::chrono::seconds limit = std::chrono::seconds(120)) {
  const auto t0 = Clock::now();
  while (!ready()) {
    if (Clock::now() - t0 > limit) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return true;
}

// Every regular file under `dir` (relative path → size). Batches may be writing meanwhile: a file
// renamed or removed between listing and reading (an atomic write's temporary) is skipped.
std::map<std::string, uintmax_t> files_under(const fs::path& dir) {
  std::map<std::string, uintmax_t> out;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code gone;
    if (!it->is_regular_file(gone)) continue;
    const uintmax_t size = it->file_size(gone);
    if (!gone) out[it->path().lexically_relative(dir).string()] = size;
  }
  return out;
}

size_t count_results(const fs::path& dir) {
  size_t n = 0;
  for (const auto& [name, size] : files_under(dir))
    if (fs::path(name).extension() == ".json" && name.rfind(".claims/", 0) != 0) ++n;
  return n;
}

// summary.csv's (material, model) → status; fails the test on a pair listed twice.
std::map<std::pair<std::string, std::string>, std::string> summary_statuses(const fs::path& dir) {
  std::ifstream in(dir / "summary.csv");
  std::string line;
  std::getline(in, line);  // material,model,procedure,fit_metric,status,...
  std::map<std::pair<std::string, std::string>, std::string> out;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ls(line);
    for (std::string field; f.size() < 5 && std::getline(ls, field, ',');) f.push_back(field);
    EXPECT_TRUE(out.emplace(std::pair(f.at(0), f.at(1)), f.at(4)).second) << "listed twice: " << line;
  }
  return out;
}

// No temporary or partial file anywhere, and .claims holds only empty lock files.
void expect_clean(const fs::path& dir) {
  for (const auto& [name, size] : files_under(dir)) {
    EXPECT_EQ(name.find(".tmp."), std::string::npos) << name;
    if (name.rfind(".claims/", 0) != 0) continue;
    EXPECT_EQ(fs::path(name).extension(), ".lock") << name;
    EXPECT_EQ(size, 0u) << name;
  }
}

class BatchSafety : public ::testing::Test {
 protected:
  static constexpr size_t kMaterials = 3;
  static void SetUpTestSuite() {
    dir_ = new fs::path(scratch_dir("batch_safety"));
    fs::create_directories(*dir_ / "data");
    const Model& ward = model_by_name("ward");
    const double alphas[kMaterials] = {0.08, 0.15, 0.3};
    const char* names[kMaterials] = {"matte-red", "satin-green", "shiny-blue"};
    for (size_t i = 0; i < kMaterials; ++i)
      merl::write(*dir_ / "data" / (std::string(names[i]) + ".binary"),
                  tabulate_model(ward, make_values(ward, {{"kd", Rgb(0.3, 0.2, 0.1)},
                                                          {"ks", Rgb(0.05, 0.08, 0.1)},
                                                          {"alpha", Rgb::Constant(alphas[i])}})));
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  // A fresh output folder and a folder for the processes' logs.
  static fs::path fresh(const std::string& name) {
    fs::remove_all(*dir_ / name);
    fs::create_directories(*dir_ / name / "logs");
    return *dir_ / name / "out";
  }
  static fs::path logs(const fs::path& out) { return out.parent_path() / "logs"; }
  // The batch: every material × `models`, --jobs 1 so fits end one at a time.
  static std::vector<std::string> batch(const fs::path& out, const std::string& models = "lambert,ward,blinn-phong") {
    return {"fit-all", (*dir_ / "data").string(), "--models", models, "--starts", "2", "--coarsen", "4",
            "--report", "ngan", "--jobs", "1", "--json", "-o", out.string()};
  }
  static std::string shell(const std::vector<std::string>& args) {
    std::string s;
    for (size_t i = 1; i < args.size(); ++i) s += (i > 1 ? " " : "") + args[i];
    return args[0] + " " + s;
  }
  static fs::path* dir_;
};
fs::path* BatchSafety::dir_ = nullptr;

TEST_F(BatchSafety, ClaimsExcludeEachOtherAndDieWithTheirProcess) {
  const fs::path lock = fit::fit_claim_file(fresh("claims"), "matte-red", "ward");
  {
    const fit::FitClaim a(lock);
    ASSERT_TRUE(a.held());
    EXPECT_FALSE(fit::FitClaim(lock).held());  // a second open file description: excluded
    EXPECT_TRUE(fit::claimed_elsewhere(lock));
  }
  EXPECT_FALSE(fit::claimed_elsewhere(lock));
  // A process holding the claim, killed with SIGKILL: the kernel releases it.
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const fit::FitClaim held(lock);
    const char ok = held.held() ? '1' : '0';
    if (::write(ready[1], &ok, 1) != 1) ::_exit(1);
    ::pause();
    ::_exit(0);
  }
  char ok = 0;
  ASSERT_EQ(::read(ready[0], &ok, 1), 1);
  EXPECT_EQ(ok, '1');
  EXPECT_FALSE(fit::FitClaim(lock).held());
  ::kill(pid, SIGKILL);
  EXPECT_EQ(wait_exit(pid), 128 + SIGKILL);
  EXPECT_TRUE(fit::FitClaim(lock).held());
  ::close(ready[0]);
  ::close(ready[1]);
}

TEST_F(BatchSafety, AFitClaimedElsewhereIsListedAsRunningElsewhereAndARerunFitsIt) {
  const fs::path out = fresh("held");
  const auto args = batch(out, "lambert,ward");
  {
    const fit::FitClaim other(fit::fit_claim_file(out, "satin-green", "ward"));
    ASSERT_TRUE(other.held());
    const CliResult r = run_cli(shell(args));
    EXPECT_EQ(r.exit_code, 0) << r.err;  // the holder saves that fit: nothing failed here
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["fitted"], 5);
    EXPECT_EQ(j["running_elsewhere"], 1);
    const auto st = summary_statuses(out);
    ASSERT_EQ(st.size(), 6u);
    const std::pair<std::string, std::string> held("satin-green", "ward");
    for (const auto& [pair, status] : st) EXPECT_EQ(status, pair == held ? "running elsewhere" : "fitted");
    EXPECT_FALSE(fs::exists(out / "satin-green" / "ward.json"));
    EXPECT_NE(r.err.find("satin-green ward: claimed by another process; tried again after the others"),
              std::string::npos) << r.err;
    EXPECT_NE(slurp(out / "table.txt").find("running in another process"), std::string::npos);
  }
  const CliResult again = run_cli(shell(args));
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.err.find("1 fitted, 5 skipped"), std::string::npos) << again.err;
  for (const auto& [pair, status] : summary_statuses(out)) EXPECT_NE(status, "running elsewhere");
  expect_clean(out);
}

TEST_F(BatchSafety, TwoConcurrentBatchesFitEachPairExactlyOnce) {
  const fs::path out = fresh("concurrent");
  const Child a = spawn(batch(out), logs(out), "a"), b = spawn(batch(out), logs(out), "b");
  ASSERT_EQ(wait_exit(a.pid), 0) << slurp(a.err);
  ASSERT_EQ(wait_exit(b.pid), 0) << slurp(b.err);
  // Each process's rows: a pair fitted by one is resumed or running elsewhere in the other.
  std::map<std::string, int> fitted_by;
  const nlohmann::json ja = nlohmann::json::parse(slurp(a.out)), jb = nlohmann::json::parse(slurp(b.out));
  for (const nlohmann::json* j : {&ja, &jb})
    for (const auto& row : (*j)["rows"])
      if (row["status"] == "fitted") ++fitted_by[row["material"].get<std::string>() + "/" + row["model"].get<std::string>()];
  EXPECT_EQ(fitted_by.size(), 9u);
  for (const auto& [pair, n] : fitted_by) EXPECT_EQ(n, 1) << pair << " fitted by both processes";
  std::cout << "fits by the two processes: " << ja["fitted"] << " + " << jb["fitted"] << "\n";
  // The summary written last lists every pair once, with its result.
  const auto st = summary_statuses(out);
  EXPECT_EQ(st.size(), 9u);
  for (const auto& [pair, status] : st) EXPECT_TRUE(status == "fitted" || status == "resumed") << status;
  EXPECT_EQ(count_results(out), 9u);
  expect_clean(out);
}

TEST_F(BatchSafety, OneOfTwoConcurrentBatchesKilledThenARerunLeavesOneValidResultPerFit) {
  const fs::path out = fresh("concurrent_killed");
  const Child a = spawn(batch(out), logs(out), "a"), b = spawn(batch(out), logs(out), "b");
  ASSERT_TRUE(wait_for([&] { return count_results(out) > 0; }));
  ::kill(a.pid, SIGKILL);
  EXPECT_EQ(wait_exit(a.pid), 128 + SIGKILL);
  const int b_exit = wait_exit(b.pid);
  std::cout << "the survivor exited " << b_exit << " with " << count_results(out) << " of 9 results saved\n";
  const CliResult rerun = run_cli(shell(batch(out)));
  ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
  // A further run refits nothing: every saved JSON matches its fit (fit_job_matches).
  const CliResult check = run_cli(shell(batch(out)));
  ASSERT_EQ(check.exit_code, 0) << check.err;
  EXPECT_NE(check.err.find("0 fitted, 9 skipped"), std::string::npos) << check.err;
  for (const auto& [name, size] : files_under(out)) {
    if (fs::path(name).extension() != ".json") continue;
    const auto j = nlohmann::json::parse(slurp(out / name));  // throws on a corrupt file
    EXPECT_EQ(j["data"]["material"].get<std::string>() + "/" + j["model"].get<std::string>() + ".json", name);
  }
  EXPECT_EQ(count_results(out), 9u);
  const auto st = summary_statuses(out);
  EXPECT_EQ(st.size(), 9u);
  for (const auto& [pair, status] : st) EXPECT_EQ(status, "resumed");
  expect_clean(out);
}

TEST_F(BatchSafety, AFileThatCannotBeWrittenStopsWithOneLineNamingItAndNoPartialFile) {
  const fs::path out = fresh("full_disk");
  // 512 bytes: below every fit JSON (lambert's, the smallest, ~960), above what the process writes
  // to stderr (~260).
  const Child c = spawn(batch(out, "lambert,ward"), logs(out), "fit-all", 512);
  EXPECT_EQ(wait_exit(c.pid), 2);
  const std::string err = slurp(c.err);
  const std::string last = err.substr(err.rfind('\n', err.size() - 2) + 1);
  EXPECT_EQ(last.rfind("brdfkit: " + out.string() + "/", 0), 0u) << err;
  EXPECT_NE(last.find(".json: cannot be written: File too large\n"), std::string::npos) << err;
  EXPECT_EQ(count_results(out), 0u);
  EXPECT_FALSE(fs::exists(out / "summary.csv"));
  expect_clean(out);

  const fs::path single = out.parent_path() / "single.json";
  const Child f = spawn({"fit", (*dir_ / "data" / "matte-red.binary").string(), "--model", "lambert", "--coarsen", "4",
                         "-o", single.string()},
                        logs(out), "fit", 512);
  EXPECT_EQ(wait_exit(f.pid), 2);
  EXPECT_EQ(slurp(f.err), "brdfkit: " + single.string() + ": cannot be written: File too large\n");
  EXPECT_FALSE(fs::exists(single));
  expect_clean(out.parent_path());

  // Without the limit the same batch completes: nothing the failed run left stands in its way.
  const CliResult r = run_cli(shell(batch(out, "lambert,ward")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("6 fitted, 0 skipped"), std::string::npos) << r.err;
}

TEST_F(BatchSafety, CtrlCKeepsEveryFinishedFitWritesTheSummaryAndExits130) {
  const fs::path out = fresh("interrupted");
  const Child c = spawn(batch(out), logs(out), "c");
  ASSERT_TRUE(wait_for([&] { return count_results(out) > 0; }));
  ::kill(c.pid, SIGINT);
  ASSERT_EQ(wait_exit(c.pid), 130) << slurp(c.err);
  EXPECT_NE(slurp(c.err).find("fit-all: interrupted: finishing the fits in flight"), std::string::npos);
  const size_t saved = count_results(out);
  std::cout << "interrupted after " << saved << " of 9 fits\n";
  EXPECT_LT(saved, 9u) << "the batch ended before the interrupt";
  // Every finished fit kept and listed; the others marked unfinished.
  const auto st = summary_statuses(out);
  ASSERT_EQ(st.size(), 9u);
  size_t fitted = 0, unfinished = 0;
  for (const auto& [pair, status] : st) {
    const bool has_json = fs::exists(out / pair.first / (pair.second + ".json"));
    if (status == "fitted") {
      ++fitted;
      EXPECT_TRUE(has_json) << pair.first << "/" << pair.second;
    } else if (status == "unfinished") {
      ++unfinished;
      EXPECT_FALSE(has_json) << pair.first << "/" << pair.second;
    }
  }
  EXPECT_EQ(fitted, saved);
  EXPECT_EQ(fitted + unfinished, 9u);
  const auto j = nlohmann::json::parse(slurp(c.out));
  EXPECT_EQ(j["interrupted"], true);
  EXPECT_EQ(j["unfinished"], unfinished);
  for (const auto& row : j["rows"]) {
    if (row["status"] != "unfinished") continue;
    EXPECT_NE(row["reason"].get<std::string>().find("interrupted"), std::string::npos) << row;
  }
  expect_clean(out);
  // A rerun completes the rest.
  const CliResult r = run_cli(shell(batch(out)));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find(std::to_string(9 - saved) + " fitted, " + std::to_string(saved) + " skipped"),
            std::string::npos) << r.err;
  EXPECT_EQ(count_results(out), 9u);
}

}  // namespace
}  // namespace brdfkit::test
