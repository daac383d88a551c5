// ALTA θd = 0 slice of MERL pink-felt (../shared/data/merl-slices).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/alta_slice.h"
#include "support/real_data.h"

using namespace brdfkit;
using namespace brdfkit::test;

namespace {
std::filesystem::path pink_felt() { return data_dir() / "merl-slices" / "pink-felt-1d.alta"; }
}  // namespace

TEST(AltaSlice, PinkFeltLoadsAndAnswersOnTheSliceOnly) {
  BRDFKIT_REQUIRE_DATA("merl-slices");
  const AltaSlice a(pink_felt());
  EXPECT_EQ(a.format(), "alta");
  ASSERT_EQ(a.cos_theta_h().size(), 90u);
  EXPECT_NEAR(a.cos_theta_h().back(), 0.999984567305837, 1e-15);
  // First data row of the file (largest cos θh).
  EXPECT_NEAR(a.values().back()[0], 0.109704419970512, 1e-15);
  EXPECT_NEAR(a.values().back()[2], 0.0616232864558697, 1e-15);
  for (size_t k = 0; k < a.cos_theta_h().size(); k += 7) {
    const Vec3d w = spherical_direction(std::acos(a.cos_theta_h()[k]), 0.7);
    const auto v = a.eval(w, w);
    ASSERT_TRUE(v.has_value());
    EXPECT_NEAR((*v - a.values()[k]).abs().maxCoeff(), 0, 1e-12);
  }
  const Vec3d w = spherical_direction(0.5, 0.0);
  EXPECT_FALSE(a.eval(w, spherical_direction(0.5, 1e-6)).has_value());
  EXPECT_FALSE(a.eval(w, spherical_direction(0.6, kPi)).has_value());
  const SampleSet s = a.samples();
  ASSERT_EQ(s.size(), 90u);
  double sum = 0;
  for (size_t k = 0; k < s.size(); ++k) {
    EXPECT_EQ((s.wi(k) - s.wo(k)).norm(), 0);
    sum += s.weight[k];
  }
  EXPECT_NEAR(sum, 2 * kPi * (1 - a.cos_theta_h().front()), 1e-12);
}

// Scale of the slice: the values are already ρ in sr⁻¹ with MERL's channel factors (1, 1.15,
// 1.66)/1500 applied. At the smallest θh (0.32°) the published fits of pink-felt predict, per
// channel, Bagher 2012 SGD: 0.1070 0.0764 0.0612 (slice/fit 1.026 1.040 1.006) and Löw 2012
// Cook-Torrance E1: 0.0994 0.0713 0.0640 (1.104 1.115 0.963). A slice without the channel factors
// would be 1/1.15 and 1/1.66 off in G and B.
TEST(AltaSlice, PinkFeltValuesAreInInverseSteradians) {
  BRDFKIT_REQUIRE_DATA("merl-slices");
  BRDFKIT_REQUIRE_DATA("published-fits");
  const AltaSlice a(pink_felt());
  const double c = a.cos_theta_h().back(), th = std::acos(c), t2 = std::pow(std::tan(th), 2);
  const Rgb slice = a.values().back();

  // Bagher 2012 SGD as the file's `conventions` state, at θd = 0 (wi = wo = h): F = F0 − F1.
  const auto sgd = nlohmann::json::parse(std::ifstream(data_dir() / "published-fits" / "bagher2012-sgd.json"))["materials"]["pink-felt"];
  const auto& kd = sgd[0]["params"]["albedo"];
  const auto& q = sgd[1]["params"];
  Rgb bagher;
  for (int i = 0; i < 3; ++i) {
    const double alpha = q["alpha"][i], p = q["p"][i], theta0 = q["theta0"][i];
    const double t = alpha + t2 / alpha;
    const double d = double(q["K"][i]) * std::exp(-t) / std::pow(t, p) / (kPi * std::pow(c, 4));
    const double g1 = th > theta0 ? 1 + double(q["Lambda"][i]) * (1 - std::exp(double(q["c"][i]) * std::pow(th - theta0, double(q["k"][i])))) : 1;
    const double f = double(q["eta"][0][i]) - double(q["eta"][1][i]);
    bagher[i] = double(kd[i]) / kPi + double(q["albedo"][i]) * d * g1 * g1 * f / (kPi * c * c);
  }
  // Löw 2012 Cook-Torrance E1: D = exp(−tan²/m²)/(m² cos⁴), V-groove G = 1 here, F(η) at cos θd = 1.
  const auto ct = nlohmann::json::parse(std::ifstream(data_dir() / "published-fits" / "low2012-cooktorrance-E1.json"))["materials"]["pink-felt"];
  const double m = ct[1]["params"]["roughness"], eta = ct[1]["params"]["eta"];
  const double f = std::pow((eta - 1) / (eta + 1), 2), d = std::exp(-t2 / (m * m)) / (m * m * std::pow(c, 4));
  Rgb low;
  for (int i = 0; i < 3; ++i)
    low[i] = double(ct[0]["params"]["albedo"][i]) / kPi + double(ct[1]["params"]["albedo"][i]) * d * f / (kPi * c * c);

  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(slice[i] / bagher[i], 1.0, 0.06) << "channel " << i;
    EXPECT_NEAR(slice[i] / low[i], 1.0, 0.15) << "channel " << i;
  }
  EXPECT_GT(std::abs(slice[2] / 1.66 / bagher[2] - 1), 0.3);  // the scale is not off by MERL's B factor
}

TEST(AltaSlice, WrongHeaderIsAClearInputError) {
  const auto dir = scratch_dir("alta_bad");
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  };
  auto error = [](const std::filesystem::path& p) {
    try {
      AltaSlice a(p);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error(write("dim.alta", "#DIM 3 3\n#PARAM_IN COS_TH\n#PARAM_OUT RGB_COLOR\n0.5 1 1 1\n")).find("#DIM 1 3"), std::string::npos);
  EXPECT_NE(error(write("in.alta", "#DIM 1 3\n#PARAM_IN RUSIN_TH_TD_PD\n#PARAM_OUT RGB_COLOR\n0.5 1 1 1\n")).find("COS_TH"), std::string::npos);
  EXPECT_NE(error(write("none.alta", "0.5 1 1 1\n")).find("header"), std::string::npos);
  const std::string e = error(write("row.alta", "#DIM 1 3\n#PARAM_IN COS_TH\n#PARAM_OUT RGB_COLOR\n0.5 1 1\n"));
  EXPECT_NE(e.find("row.alta:4"), std::string::npos) << e;
  EXPECT_NE(e.find("3 values, expected 4"), std::string::npos) << e;
}
