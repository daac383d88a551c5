// Cornell scattered spectral measurements (../shared/data/cornell, DESIGN.md §2).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <map>
#include <optional>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/cornell.h"
#include "brdfkit/measured/load.h"
#include "support/real_data.h"

using namespace brdfkit;
using namespace brdfkit::test;

TEST(CornellReal, EveryFileLoadsWithSolidAngleWeights) {
  BRDFKIT_REQUIRE_DATA("cornell");
  for (const auto& name : kCornellMaterials) {
    SCOPED_TRACE(name);
    const CornellBrdf c(cornell_file(name));
    EXPECT_EQ(c.format(), "cornell");
    ASSERT_EQ(c.wavelengths().size(), 31u);
    EXPECT_EQ(c.wavelengths().front(), 400);
    EXPECT_EQ(c.wavelengths().back(), 700);
    const SampleSet s = c.samples();
    ASSERT_EQ(s.size(), 1439u);
    EXPECT_FALSE(c.eval(s.wi(0), s.wo(0)).has_value());  // scattered: no eval anywhere
    for (size_t k = 0; k < s.size(); ++k) {
      ASSERT_TRUE(s.value(k).allFinite());
      ASSERT_GT(s.weight[k], 0);
      ASSERT_LE(s.wo(k).y(), 1e-6);  // φs in the half plane [−180°, 0°]
    }
    const auto thetas = c.theta_i_values();
    ASSERT_EQ(thetas.size(), 8u);
    for (size_t j = 0; j < 8; ++j) {
      EXPECT_NEAR(thetas[j], (10.0 * (j + 1)) * kPi / 180, 1e-5);
      // Σ weight over one θi = 2π (the half plane mirrored), less ring 0's band (1/400 of the
      // hemisphere) where that ring has no sample.
      double sum = 0;
      for (size_t k = 0; k < s.size(); ++k)
        if (std::abs(theta_of(s.wi(k)) - thetas[j]) < 1e-5) sum += s.weight[k];
      EXPECT_NEAR(sum, 2 * kPi, 2 * kPi / 400 + 1e-9);
    }
  }
}

// Luminance albedo Σ ρ cos θs · weight in (0, 1] where the data are dense enough (θi ≤ 60°).
// Measured (10°…60°): acryl_blue 0.009 0.005 0.006 0.101 0.175 0.145, garnet_red 0.087…0.165,
// krylon_blue 0.096…0.174.
TEST(CornellReal, AlbedoFromSamplesIsInUnitIntervalUpTo60Degrees) {
  BRDFKIT_REQUIRE_DATA("cornell");
  for (const auto& name : kCornellMaterials) {
    const CornellBrdf c(cornell_file(name));
    const auto albedos = c.albedos_from_samples();
    ASSERT_EQ(albedos.size(), 8u);
    for (const auto& [t, a] : albedos) {
      if (t > kPi / 3 + 1e-6) continue;
      SCOPED_TRACE(name + " θi = " + std::to_string(t * 180 / kPi));
      EXPECT_GT(luminance(a), 0);
      EXPECT_LE(luminance(a), 1);
      EXPECT_TRUE((c.directional_albedo_from_samples(t) == a).all());
    }
  }
}

// DESIGN.md §2: saturated colours are out of the sRGB gamut; acryl_blue's R and G albedo at
// θi ≤ 30° is ≈ 0 (−0.002…0.003), and stays so (no clamping). Measured: R 0.0033 −0.0006 −0.0000,
// G 0.0027 −0.0018 −0.0013.
TEST(CornellReal, AcrylBlueRedAndGreenAlbedoNearZeroAndKeptNegative) {
  BRDFKIT_REQUIRE_DATA("cornell");
  const CornellBrdf c(cornell_file("acryl_blue"));
  bool any_negative = false;
  for (const auto& [t, a] : c.albedos_from_samples()) {
    if (t > kPi / 6 + 1e-6) continue;
    EXPECT_LT(std::abs(a[0]), 0.005);
    EXPECT_LT(std::abs(a[1]), 0.005);
    EXPECT_GT(a[2], 0.08);
    any_negative = any_negative || a[0] < 0 || a[1] < 0;
  }
  EXPECT_TRUE(any_negative);
}

namespace {

// ρ's luminance at (θi, θs, |Δφ|) interpolated from the samples: linearly in θi between the
// file's incidence angles, in θs between rings, in |φs| along a ring (no extrapolation, and no
// interpolation across a gap wider than 0.6 rad: the missing retro-reflection neighbourhood).
class CornellInterpolator {
 public:
  explicit CornellInterpolator(const SampleSet& s) {
    for (size_t k = 0; k < s.size(); ++k)
      data_[key(theta_of(s.wi(k)))][key(theta_of(s.wo(k)))].emplace_back(std::abs(phi_of(s.wo(k))), luminance(s.value(k)));
    for (auto& [ti, rings] : data_)
      for (auto& [ts, ring] : rings) std::sort(ring.begin(), ring.end());
  }
  std::optional<double> operator()(double ti, double ts, double dphi) const {
    return between(data_, ti, [&](const Rings& rings) {
      return between(rings, ts, [&](const Ring& ring) { return along(ring, dphi); });
    });
  }

 private:
  using Ring = std::vector<std::pair<double, double>>;
  using Rings = std::map<long, Ring>;
  static long key(double angle) { return std::lround(angle * 1e5); }
  static std::optional<double> along(const Ring& ring, double dphi) {
    if (ring.size() == 1) return ring[0].second;  // θs = 0: no azimuth
    for (size_t i = 0; i + 1 < ring.size(); ++i)
      if (dphi >= ring[i].first - 1e-9 && dphi <= ring[i + 1].first + 1e-9) {
        const double gap = ring[i + 1].first - ring[i].first;
        if (gap > 0.6) return std::nullopt;
        const double t = gap > 0 ? (dphi - ring[i].first) / gap : 0;
        return (1 - t) * ring[i].second + t * ring[i + 1].second;
      }
    return std::nullopt;
  }
  template <class Map, class F> static std::optional<double> between(const Map& m, double x, F inner) {
    auto hi = m.lower_bound(key(x));
    if (hi == m.end()) return std::nullopt;
    if (hi->first == key(x)) return inner(hi->second);
    if (hi == m.begin()) return std::nullopt;
    const auto lo = std::prev(hi);
    const auto a = inner(lo->second), b = inner(hi->second);
    if (!a || !b) return std::nullopt;
    const double t = (x - lo->first * 1e-5) / ((hi->first - lo->first) * 1e-5);
    return (1 - t) * *a + t * *b;
  }
  std::map<long, Rings> data_;
};

// Median over samples of max(r, 1/r), r = ρ(swapped) / ρ, on luminance.
std::pair<double, size_t> reciprocity_factor(const CornellBrdf& c) {
  const SampleSet s = c.samples();
  const CornellInterpolator interp(s);
  std::vector<double> factors;
  for (size_t k = 0; k < s.size(); ++k) {
    const auto swapped = interp(theta_of(s.wo(k)), theta_of(s.wi(k)), std::abs(phi_of(s.wo(k))));
    const double v = luminance(s.value(k));
    if (!swapped || *swapped <= 0 || v <= 0) continue;
    factors.push_back(std::max(*swapped / v, v / *swapped));
  }
  return {median(factors), factors.size()};
}

}  // namespace

// DESIGN.md §2: these data are far from reciprocal for some materials (median factor 1.03 for
// garnet_red). The swapped configuration is never a sample (θs rings ≠ θi values), so it is
// interpolated (CornellInterpolator), which adds its own error on the lobes: measured here over
// 998 pairs, garnet_red 1.066, krylon_blue 1.131, acryl_blue 1.418.
TEST(CornellReal, ReciprocityFactorsAsMeasured) {
  BRDFKIT_REQUIRE_DATA("cornell");
  const std::map<std::string, std::pair<double, double>> expected = {
      {"garnet_red", {1.0, 1.10}}, {"krylon_blue", {1.05, 1.20}}, {"acryl_blue", {1.25, 1.60}}};
  for (const auto& name : kCornellMaterials) {
    const auto [factor, pairs] = reciprocity_factor(CornellBrdf(cornell_file(name)));
    std::printf("  %-12s median reciprocity factor %.4f over %zu pairs\n", name.c_str(), factor, pairs);
    EXPECT_GT(pairs, 900u) << name;
    EXPECT_GT(factor, expected.at(name).first) << name;
    EXPECT_LT(factor, expected.at(name).second) << name;
  }
}

namespace {
std::string load_error(const std::filesystem::path& file) {
  try {
    CornellBrdf c(file, data_dir() / "cie");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(CornellReal, BadInputIsAClearInputError) {
  BRDFKIT_REQUIRE_DATA("cornell");
  BRDFKIT_REQUIRE_DATA("cie");
  const auto dir = scratch_dir("cornell_bad");
  std::ifstream in(cornell_file("garnet_red"), std::ios::binary);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  auto write = [&](const std::string& name, const std::vector<std::string>& ls) {
    std::ofstream out(dir / name, std::ios::binary);
    for (const auto& l : ls) out << l << "\n";
    return dir / name;
  };
  // Find the first sample line and cut its last value.
  auto short_line = lines;
  size_t first_sample = 0;
  for (size_t i = 0; i < lines.size(); ++i)
    if (lines[i].size() > 100 && lines[i][0] != '#') {
      first_sample = i;
      break;
    }
  ASSERT_GT(first_sample, 0u);
  short_line[first_sample + 3] = short_line[first_sample + 3].substr(0, short_line[first_sample + 3].rfind(' '));
  const std::string e1 = load_error(write("short.brdf", short_line));
  EXPECT_NE(e1.find("short.brdf:" + std::to_string(first_sample + 4)), std::string::npos) << e1;
  EXPECT_NE(e1.find("34 values, expected 35"), std::string::npos) << e1;

  auto bad_number = lines;
  bad_number[first_sample] += " x1";
  EXPECT_NE(load_error(write("nan.brdf", bad_number)).find("not a number: 'x1'"), std::string::npos);

  const std::string e3 = load_error(write("header.brdf", {"# nothing", "31.5"}));
  EXPECT_NE(e3.find("wavelength count"), std::string::npos) << e3;
  EXPECT_NE(load_error(write("empty.brdf", {"# only comments"})).find("no wavelength count"), std::string::npos);
  EXPECT_THROW(CornellBrdf(cornell_file("garnet_red"), dir / "no-cie-here"), InputError);
}

// A file copied away from ../shared/data (no cie/ folder near it, no $BRDFKIT_CIE_DIR) reads with
// the compiled-in CIE tables: the same RGB, bit for bit, as the file in place read with the shared
// data's own tables (the same numbers).
TEST(CornellReal, CopyOutsideTheDataFolderGivesTheSameRgb) {
  BRDFKIT_REQUIRE_DATA("cornell");
  BRDFKIT_REQUIRE_DATA("cie");
  const ScopedEnv no_override("BRDFKIT_CIE_DIR", nullptr);
  const auto copy = scratch_dir("cornell_copy") / "garnet_red.brdf";
  std::filesystem::copy_file(cornell_file("garnet_red"), copy);
  const SampleSet moved = load_measured(copy)->samples();
  const SampleSet in_place = CornellBrdf(cornell_file("garnet_red"), data_dir() / "cie").samples();
  ASSERT_EQ(moved.size(), in_place.size());
  for (size_t k = 0; k < moved.size(); ++k)
    for (size_t c = 0; c < 3; ++c) ASSERT_EQ(moved.rgb[c][k], in_place.rgb[c][k]) << "sample " << k << " channel " << c;
  std::filesystem::remove_all(copy.parent_path());
}

namespace {

// garnet_red's lines with sample `sample` (0-based among sample lines) given `values` from its
// first spectral value on; returns the new file and the 1-based line number of that sample.
std::pair<std::filesystem::path, size_t> garnet_with(const std::filesystem::path& file, size_t sample,
                                                     const std::vector<std::string>& values) {
  std::ifstream in(cornell_file("garnet_red"), std::ios::binary);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  size_t line = 0;
  for (size_t i = 0, seen = 0; i < lines.size(); ++i)
    if (lines[i].size() > 100 && lines[i][0] != '#' && seen++ == sample) line = i;
  std::istringstream ss(lines[line]);
  std::vector<std::string> tokens{std::istream_iterator<std::string>(ss), {}};
  std::copy(values.begin(), values.end(), tokens.begin() + 4);
  std::string joined;
  for (const auto& t : tokens) joined += (joined.empty() ? "" : " ") + t;
  lines[line] = joined + "\r";
  std::ofstream out(file, std::ios::binary);
  for (const auto& l : lines) out << l << "\n";
  return {file, line + 1};
}

}  // namespace

// Cornell files are refused, not patched, when a value cannot be a measurement (cornell.cpp says
// why): a non-finite token, or a value beyond kMaxMeasuredValue, whose sums overflow.
TEST(CornellReal, NonFiniteOrHugeValuesAreRefused) {
  BRDFKIT_REQUIRE_DATA("cornell");
  const auto dir = scratch_dir("cornell_huge");
  const std::vector<std::string> huge(31, "1.7976931348623157e308");
  struct Case {
    std::string name;
    std::vector<std::string> values;
    std::string expect;
  };
  const std::vector<Case> cases = {
      {"huge.brdf", huge, "spectral value 0 (400 nm) is 1.7976931348623157e+308"},
      {"negative_huge.brdf", {"0.01", "0.01", "-1e300"}, "spectral value 2 (420 nm) is -1e+300"},
      {"nan.brdf", {"nan"}, "not a number: 'nan'"},
      {"inf.brdf", {"0.01", "inf"}, "not a number: 'inf'"},
  };
  for (const auto& c : cases) {
    const auto [file, line] = garnet_with(dir / c.name, 5, c.values);
    std::string what;
    try {
      CornellBrdf b(file);
    } catch (const InputError& e) {
      what = e.what();
    }
    EXPECT_NE(what.find(file.string() + ":" + std::to_string(line) + ": "), std::string::npos) << what;
    EXPECT_NE(what.find(c.expect), std::string::npos) << what;
  }
  std::filesystem::remove_all(dir);
}
