// A saved-fit input found while writing the fit-record fuzz target (fuzz/fuzz_fit_record.cpp):
// a value the reader must refuse, naming the file and the field, rather than read as another.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "brdfkit/core/error.h"
#include "brdfkit/fit/fit_record.h"

namespace brdfkit {
namespace {

std::filesystem::path write_fit(const std::string& name, const std::string& grid_coarsen) {
  const auto path = std::filesystem::path(::testing::TempDir()) / (name + "-" + std::to_string(::getpid()) + ".json");
  std::ofstream(path) << R"({"format": "brdfkit-fit", "model": "lambert", "params": [{"name": "kd", "values": [0.5, 0.4, 0.3]}],
                            "grid_coarsen": )"
                      << grid_coarsen << "}";
  return path;
}

// get<int>() wrapped 2^32 + 1 to 1: the record read as computed on the papers' grids.
TEST(FitRecordFuzzRegressions, GridCoarsenBeyondIntIsRefusedNotWrapped) {
  const auto wrapped = write_fit("fit-coarsen-wrap", "4294967297");
  try {
    const fit::FitRecord r = fit::load_fit_record(wrapped);
    ADD_FAILURE() << "read grid_coarsen 4294967297 as " << r.coarsen;
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), wrapped.string() + ": field 'grid_coarsen': must be an integer in [1, 2147483647]");
  }
  const auto huge = write_fit("fit-coarsen-huge", "18446744073709551615");
  EXPECT_THROW((void)fit::load_fit_record(huge), InputError);
  const auto fine = write_fit("fit-coarsen-3", "3");
  EXPECT_EQ(fit::load_fit_record(fine).coarsen, 3);
  for (const auto& p : {wrapped, huge, fine}) std::filesystem::remove(p);
}

}  // namespace
}  // namespace brdfkit
