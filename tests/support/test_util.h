#pragma once
// Shared helpers for the test suite: where the shared data lives, running the CLI.
#include <gtest/gtest.h>

#include <unistd.h>
#include <sys/wait.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace brdfkit::test {

inline std::filesystem::path data_dir() { return BRDFKIT_TEST_DATA_DIR; }

// Skips the current test with a printed reason when ../shared/data/<sub> is absent.
#define BRDFKIT_REQUIRE_DATA(sub)                                                                       \
  do {                                                                                                  \
    if (!std::filesystem::exists(::brdfkit::test::data_dir() / (sub)))                                  \
      GTEST_SKIP() << "shared data folder " << (::brdfkit::test::data_dir() / (sub)).string()           \
                   << " is absent";                                                                    \
  } while (0)

struct CliResult {
  int exit_code;
  std::string out;  // stdout
  std::string err;  // stderr
};

// Runs the brdfkit executable with `args` (a shell-quoted string).
inline CliResult run_cli(const std::string& args) {
  const auto dir = std::filesystem::temp_directory_path() / ("brdfkit_cli_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" + std::to_string(reinterpret_cast<uintptr_t>(&args)));
  std::filesystem::create_directories(dir);
  const auto out = dir / "out", err = dir / "err";
  const std::string cmd = std::string(BRDFKIT_CLI_PATH) + " " + args + " >" + out.string() + " 2>" + err.string();
  const int status = std::system(cmd.c_str());
  auto slurp = [](const std::filesystem::path& p) {
    std::string s;
    if (FILE* f = std::fopen(p.c_str(), "rb")) {
      char buf[4096];
      size_t n;
      while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
      std::fclose(f);
    }
    return s;
  };
  CliResult r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
  std::filesystem::remove_all(dir);
  return r;
}

// The scratch folders of this process, removed when it ends (a failed test's too: the files of a
// failure are in its message, and a leftover folder per test process would fill /tmp).
struct ScratchDirs {
  std::vector<std::filesystem::path> dirs;
  ~ScratchDirs() {
    std::error_code ignored;
    for (const auto& d : dirs) std::filesystem::remove_all(d, ignored);
  }
};

// A fresh empty folder for one test's files, removed at the latest when the process ends.
inline std::filesystem::path scratch_dir(const std::string& name) {
  static ScratchDirs made;
  auto dir = std::filesystem::temp_directory_path() / ("brdfkit_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  made.dirs.push_back(dir);
  return dir;
}

// Sets (or, with nullptr, unsets) an environment variable for one scope; the old value comes back
// at its end. Child processes (run_cli) inherit what is set.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    value ? ::setenv(name, value, 1) : ::unsetenv(name);
  }
  ~ScopedEnv() { old_ ? ::setenv(name_.c_str(), old_->c_str(), 1) : ::unsetenv(name_.c_str()); }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  std::string name_;
  std::optional<std::string> old_;
};

}  // namespace brdfkit::test
