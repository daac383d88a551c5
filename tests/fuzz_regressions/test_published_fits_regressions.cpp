// Inputs the published-fits fuzz target (fuzz/fuzz_published_fits.cpp) and its review found: each
// must be refused with a one-line InputError naming the file, the material and the field.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "brdfkit/core/error.h"
#include "brdfkit/models/published_fits.h"

namespace brdfkit {
namespace {

std::filesystem::path write_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::path(::testing::TempDir()) / (name + "-" + std::to_string(::getpid()) + ".json");
  std::ofstream(path) << text;
  return path;
}

// A Bagher file of one material whose specular lobe has these "p" and "alpha".
std::string bagher_file(const std::string& p, const std::string& alpha) {
  return R"({"materials": {"m": [{"lobe": "Lambertian", "params": {"albedo": [0.05, 0.04, 0.03]}},
           {"lobe": "Bagher", "params": {"albedo": [0.03, 0.6, 0.27], "alpha": )" +
         alpha + R"(, "p": )" + p + R"(, "eta": [[6.0, 0.24, 0.58], [5.0, 0.18, 0.48]]}}]}})";
}

// "lobe": 7 made nlohmann's value("lobe", "") throw its type_error, which the CLI reports as an
// internal error (exit 1) naming nothing.
TEST(PublishedFitsFuzzRegressions, LobeNameThatIsNotAStringIsBadInput) {
  const auto first = write_file("pub-lobe-first",
                                R"({"materials": {"m": [{"lobe": "Lambertian", "params": {"albedo": 0.5}},
                                                        {"lobe": 7, "params": {}}]}})");
  try {
    (void)PublishedFits::read(first);
    ADD_FAILURE() << "read a lobe named 7";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), first.string() + ": material 'm': a lobe whose 'lobe' is not a string");
  }
  // The first material names the lobe; a later one's bad name is found when it is loaded.
  const auto later = write_file("pub-lobe-later",
                                R"({"materials": {"a": [{"lobe": "Lambertian", "params": {"albedo": 0.5}},
                                                        {"lobe": "LowSmooth", "params": {"A": 1, "B": 10, "C": 1, "eta": 1.5}}],
                                                  "b": [{"lobe": ["LowSmooth"], "params": {}}]}})");
  const PublishedFits fits = PublishedFits::read(later);
  EXPECT_NO_THROW((void)fits.brdf("a"));
  try {
    (void)fits.brdf("b");
    ADD_FAILURE() << "loaded a lobe named [\"LowSmooth\"]";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), later.string() + ": material 'b': a lobe whose 'lobe' is not a string");
  }
  std::filesystem::remove(first);
  std::filesystem::remove(later);
}

// p = 4.45 loaded "as published" gave a BRDF whose first evaluation threw "upper_gamma: order s =
// -3.450000 must be > -1", naming neither the file nor the parameter.
TEST(PublishedFitsFuzzRegressions, ValueWhereTheModelIsUndefinedNamesFileMaterialAndParameter) {
  const auto file = write_file("pub-sgd-p", bagher_file("[0.46, 4.45, 0.53]", "[0.015, 0.03, 0.05]"));
  const PublishedFits fits = PublishedFits::read(file);
  try {
    (void)fits.brdf("m");
    ADD_FAILURE() << "loaded p = 4.45";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(file.string() + ": material 'm': parameter 'p' = 4.45 (channel G) is outside the model's bounds [0, 1.95] "
                                            "and the model is not defined there: upper_gamma: order s = -3.450000",
                            0),
              0u)
        << message;
  }
  std::filesystem::remove(file);
}

// Outside the bounds but where the model is defined, a value still loads as published (one of
// Löw 2012's Cook-Torrance roughnesses is 2.09 > 2).
TEST(PublishedFitsFuzzRegressions, ValueOutsideTheBoundsWhereTheModelIsDefinedLoads) {
  const auto file = write_file("pub-ct-alpha", R"({"materials": {"m": [
      {"lobe": "Lambertian", "params": {"albedo": [0.1, 0.1, 0.1]}},
      {"lobe": "LowCookTorrance", "params": {"albedo": [0.05, 0.04, 0.05], "roughness": 2.09422, "eta": 1.46}}]}})");
  const Brdf brdf = PublishedFits::read(file).brdf("m");
  EXPECT_EQ(brdf.values().values[1][size_t(find_param(brdf.model().params(), "alpha"))], 2.09422);
  EXPECT_TRUE(brdf.eval(spherical_direction(0.3, 0.0), spherical_direction(0.4, kPi)).allFinite());
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace brdfkit
