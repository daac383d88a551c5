// Bad input of every kind the command line meets ends the same way: exit 2 and one line on stderr
// that names the file, field or option, with no raw control bytes, no "internal error" and no
// file left behind: file names that are not UTF-8 (JSON cannot hold them), an output path that
// is a folder, fit-all inputs that do not exist, NUL and other control bytes in names, argument
// errors of the parser, and count settings out of their range.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>

#include "brdfkit/fit/batch/fit_batch.h"
#include "brdfkit/fit/settings/fit_settings.h"
#include "brdfkit/measured/merl.h"
#include "support/fit_test_util.h"
#include "support/output_lines.h"
#include "support/test_util.h"

namespace brdfkit::test {
namespace {

namespace fs = std::filesystem;

// `s` as one shell word, byte for byte (run_cli hands its arguments to the shell).
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// True when `s` holds a byte a terminal acts on (C0 controls and DEL) other than the newline
// that ends each line.
bool has_raw_control_byte(const std::string& s) {
  return std::any_of(s.begin(), s.end(), [](char c) {
    const auto b = static_cast<unsigned char>(c);
    return (b < 0x20 && b != '\n') || b == 0x7f;
  });
}

// Exit 2 with exactly one clean line on stderr that holds `needle`.
void expect_refused(const std::string& args, const std::string& needle) {
  const CliResult r = run_cli(args);
  SCOPED_TRACE(args + "\nstderr: " + r.err);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  EXPECT_NE(r.err.find(needle), std::string::npos);
  EXPECT_EQ(r.err.find("internal error"), std::string::npos);
  EXPECT_EQ(r.err.find("Usage:"), std::string::npos);
  EXPECT_FALSE(has_raw_control_byte(r.err));
  EXPECT_EQ(r.out, "");
}

class CliInputErrors : public ::testing::Test {
 protected:
  // One small Lambert material (fits of it take well under a second at coarsen 4).
  static void SetUpTestSuite() {
    dir_ = new fs::path(scratch_dir("cli_input_errors"));
    const Model& m = model_by_name("lambert");
    merl::write(*dir_ / "lambert.binary", tabulate_model(m, make_values(m, {{"kd", Rgb(0.3, 0.2, 0.1)}})));
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  static std::string path(const std::string& name) { return (*dir_ / name).string(); }
  static std::string fit(const std::string& file, const std::string& extra) {
    return "fit " + quoted(file) + " --model lambert --coarsen 4 --report ngan " + extra;
  }
  static fs::path* dir_;
};
fs::path* CliInputErrors::dir_ = nullptr;

TEST_F(CliInputErrors, FileNameThatIsNotUtf8IsRefusedNamingIt) {
  // Linux allows any byte but '/' and NUL in a name; the fit's JSON stores the name as text.
  fs::create_directories(path("latin1"));
  const std::string bad = path("latin1/caf\xe9.binary");
  fs::copy_file(path("lambert.binary"), bad);
  expect_refused(fit(bad, "-o " + path("latin1.json")), "caf\\xe9.binary");
  EXPECT_FALSE(fs::exists(path("latin1.json")));
  expect_refused("fit-all " + path("latin1") + " --models lambert --coarsen 4 --report ngan -o " + path("latin1_out"),
                 "caf\\xe9.binary");
  EXPECT_FALSE(fs::exists(path("latin1_out")));
  // Any --json output: the string JSON cannot hold is named (info prints its source line first).
  const CliResult info = run_cli("info " + quoted(bad) + " --json");
  EXPECT_EQ(info.exit_code, 2) << info.err;
  EXPECT_NE(info.err.find("brdfkit: " + path("latin1/caf\\xe9.binary") + ": not valid UTF-8"), std::string::npos)
      << info.err;
  EXPECT_FALSE(has_raw_control_byte(info.err)) << info.err;
}

TEST_F(CliInputErrors, OutputPathThatIsAFolderIsRefusedNamingIt) {
  fs::create_directories(path("a_folder"));
  expect_refused(fit(path("lambert.binary"), "-o " + path("a_folder")), path("a_folder"));
  expect_refused("tabulate lambert --param kd=0.5 -o " + path("a_folder"), path("a_folder"));
  EXPECT_TRUE(fs::is_directory(path("a_folder")));
  EXPECT_TRUE(fs::is_empty(path("a_folder")));
  for (const auto& e : fs::directory_iterator(*dir_))  // no temporary left beside it
    EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << e.path();
}

TEST_F(CliInputErrors, FitAllWithAMissingInputWritesNothing) {
  const std::string tail = " --models lambert --coarsen 4 --report ngan -o ";
  expect_refused("fit-all " + path("lambert.binary") + " " + path("no-such.binary") + tail + path("missing_file_out"),
                 path("no-such.binary"));
  EXPECT_FALSE(fs::exists(path("missing_file_out")));
  expect_refused("fit-all " + path("no-such-folder") + "/" + tail + path("missing_folder_out"),
                 path("no-such-folder"));
  EXPECT_FALSE(fs::exists(path("missing_folder_out")));
}

TEST_F(CliInputErrors, ControlBytesInNamesAreEscapedNotEchoed) {
  // A NUL (JSON can hold one as \u0000) must not cut the message short; ESC must not reach the terminal.
  std::ofstream(path("nul.json")) << R"({"model": "no\u0000such\u001b[2Jmodel", "params": []})";
  expect_refused("error " + path("lambert.binary") + " --params " + path("nul.json"), "no\\x00such\\x1b[2Jmodel");
  expect_refused("check lambert --param " + quoted("k\nd\x01=0.5"), "k\\nd\\x01");
  expect_refused("models " + quoted("no\x7fmodel\tx"), "no\\x7fmodel\\tx");
}

TEST_F(CliInputErrors, ArgumentErrorsAreOneLineNamingTheSubcommand) {
  const std::string file = path("lambert.binary");
  const std::pair<std::string, std::string> cases[] = {
      {"fit " + file + " --model lambert --bogus -o " + path("x.json"), "brdfkit fit: "},
      {"fit " + file + " --model lambert", "brdfkit fit: "},                                   // -o missing
      {"fit " + file + " --model lambert --starts abc -o " + path("x.json"), "brdfkit fit: "},  // not a number
      {"fit-all " + file + " --models lambert --jobs -o " + path("x_out"), "brdfkit fit-all: "},
      {"no-such-subcommand", "brdfkit: "},
  };
  for (const auto& [args, prefix] : cases) {
    expect_refused(args, "--help");
    const CliResult r = run_cli(args);
    EXPECT_EQ(r.err.rfind(prefix, 0), 0u) << args << "\n" << r.err;
  }
  EXPECT_FALSE(fs::exists(path("x.json")));
}

TEST_F(CliInputErrors, CountSettingsHaveADocumentedRange) {
  using fit::FitSettings;
  const std::string file = path("lambert.binary");
  const auto range = [](int hi) { return "[1, " + std::to_string(hi) + "]"; };
  expect_refused(fit(file, "--starts 1000000 -o " + path("x.json")), "--starts");
  expect_refused(fit(file, "--starts 1000000 -o " + path("x.json")), range(FitSettings::kMaxStarts));
  expect_refused(fit(file, "--max-iterations 100000000 -o " + path("x.json")), range(FitSettings::kMaxIterations));
  expect_refused("fit-all " + file + " --models lambert --starts 1000000 -o " + path("x_out"), "--starts");
  expect_refused("analyze " + file + " --what albedo --coarsen 1000", "--coarsen");
  expect_refused("analyze " + file + " --what albedo --coarsen 1000", range(FitSettings::kMaxCoarsen));
  expect_refused("analyze " + file + " --what ndf --starts 1000000", range(FitSettings::kMaxStarts));
  EXPECT_FALSE(fs::exists(path("x.json")));
  EXPECT_FALSE(fs::exists(path("x_out")));
  // The help says what each count accepts, on the option's own line ("1 to 1000" alone would
  // also be found in --max-iterations' "1 to 100000").
  const auto states_range = [](const std::string& help, const std::string& flag, int hi) {
    const auto line = line_led_by(help, flag);
    const std::string range = "1 to " + std::to_string(hi) + ")";
    const bool ends = line && line->size() > range.size() && line->ends_with(range) &&
                      !std::isdigit(static_cast<unsigned char>((*line)[line->size() - range.size() - 1]));
    EXPECT_TRUE(ends) << flag << " " << hi << "\n" << help;
  };
  for (const char* sub : {"fit", "fit-all"}) {
    const CliResult help = run_cli(std::string(sub) + " --help");
    EXPECT_EQ(help.exit_code, 0);
    states_range(help.out, "--starts", FitSettings::kMaxStarts);
    states_range(help.out, "--max-iterations", FitSettings::kMaxIterations);
    states_range(help.out, "--coarsen", FitSettings::kMaxCoarsen);
  }
  states_range(run_cli("fit-all --help").out, "-j,--jobs", fit::BatchSettings::kMaxJobs);
}

}  // namespace
}  // namespace brdfkit::test
