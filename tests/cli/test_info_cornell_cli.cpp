// `brdfkit info` on Cornell (spectral) files: a copy away from ../shared/data reads with the
// compiled-in CIE tables and reports the same numbers as the file in place; a value no measurement
// can have is refused with exit 2. Skipped with a printed reason when the shared data are absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/real_data.h"

using namespace brdfkit;
using namespace brdfkit::test;
namespace fs = std::filesystem;

namespace {

// `info --json FILE`'s entry for the file, without its path (the only field that names where it is).
nlohmann::json info_entry(const fs::path& file) {
  const auto r = run_cli("info --json '" + file.string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  if (r.exit_code != 0) return nullptr;
  auto entry = nlohmann::json::parse(r.out)["files"][0];
  entry.erase("path");
  return entry;
}

}  // namespace

TEST(InfoCornellCli, CopyOutsideTheDataFolderGivesTheSameNumbers) {
  BRDFKIT_REQUIRE_DATA("cornell");
  BRDFKIT_REQUIRE_DATA("cie");
  const auto dir = scratch_dir("info_cornell_copy");
  const fs::path copy = dir / "garnet_red.brdf";
  fs::copy_file(cornell_file("garnet_red"), copy);
  nlohmann::json in_place, moved;
  {
    const ScopedEnv shared_tables("BRDFKIT_CIE_DIR", (data_dir() / "cie").c_str());
    in_place = info_entry(cornell_file("garnet_red"));
  }
  {
    const ScopedEnv built_in_tables("BRDFKIT_CIE_DIR", nullptr);
    moved = info_entry(copy);
  }
  ASSERT_FALSE(in_place.is_null());
  ASSERT_FALSE(moved.is_null());
  EXPECT_EQ(moved, in_place) << "copy:\n" << moved.dump(1) << "\nin place:\n" << in_place.dump(1);
  EXPECT_EQ(moved["valid"], 1439);
  fs::remove_all(dir);
}

// Every value of one sample line at the largest double: its RGB and the albedo sums overflow
// unless the reader refuses the file (cornell.cpp).
TEST(InfoCornellCli, HugeSpectralValueIsRefused) {
  BRDFKIT_REQUIRE_DATA("cornell");
  const auto dir = scratch_dir("info_cornell_huge");
  std::ifstream in(cornell_file("garnet_red"), std::ios::binary);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  const auto first = size_t(std::find_if(lines.begin(), lines.end(), [](const std::string& l) { return l.size() > 100 && l[0] != '#'; }) -
                            lines.begin());
  ASSERT_LT(first + 2, lines.size());
  std::string& line = lines[first + 2];
  size_t cut = 0;
  for (int k = 0; k < 4; ++k) cut = line.find(' ', cut) + 1;
  line = line.substr(0, cut);
  for (int k = 0; k < 31; ++k) line += (k ? " " : "") + std::string("1.7976931348623157e308");
  line += "\r";
  const fs::path file = dir / "huge.brdf";
  {
    std::ofstream out(file, std::ios::binary);
    for (const auto& l : lines) out << l << "\n";
  }
  const auto r = run_cli("info '" + file.string() + "'");
  std::printf("exit %d, stderr: %s", r.exit_code, r.err.c_str());
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("brdfkit: " + file.string() + ":" + std::to_string(first + 3) + ": spectral value 0 (400 nm)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.out.find("inf"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
  fs::remove_all(dir);
}
