// Metrics on scattered measured samples (fit/metric_samples.h): a synthetic Cornell-like
// layout sampled from a known model, the real Cornell files through the CLI, the ALTA slice.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/fit/engine/fit_model.h"
#include "brdfkit/measured/alta_slice.h"
#include "support/fit_test_util.h"
#include "support/test_util.h"

namespace brdfkit::fit {
namespace {

using test::make_values;

constexpr double kDeg = kPi / 180;

// Scattered samples of a model in the layout of the Cornell files (measured/cornell.h): θi =
// 10°…80°, rings 1 − cos θo = (k/10)², k = 0…9, `per_ring` azimuths on the half plane
// φo ∈ [−180°, 0°], weight = the ring's band of solid angle / its sample count; as a scattered
// file, which eval() answers nothing for.
test::ScatteredData scattered_model(const Model& model, const ParamValues& values, int per_ring = 19) {
  SampleSet s;
  const Brdf brdf(model, values);
  auto edge = [](int k) { return k <= 0 ? 0.0 : k >= 10 ? 1.0 : std::pow((k - 0.5) / 10, 2); };
  for (int i = 1; i <= 8; ++i)
    for (int k = 0; k < 10; ++k) {
      const double theta_o = std::acos(1 - std::pow(k / 10.0, 2));
      const int n = k == 0 ? 1 : per_ring;
      for (int j = 0; j < n; ++j) {
        const double phi = n == 1 ? 0.0 : -kPi * j / (n - 1);
        const Vec3d wi = spherical_direction(i * 10 * kDeg, 0.0), wo = spherical_direction(theta_o, phi);
        s.push_back(wi, wo, brdf.eval(wi, wo), 2 * kPi * (edge(k + 1) - edge(k)) / n, true);
      }
    }
  return test::ScatteredData(std::move(s), "synthetic-scattered");
}

// Incidence band of θi = 10°·g between the midpoints to its neighbours (metric_samples.h).
double band(int g) {
  const double lo = g == 1 ? 0.0 : (g - 0.5) * 10 * kDeg, hi = g == 8 ? kPi / 2 : (g + 0.5) * 10 * kDeg;
  return 2 * kPi * (std::cos(lo) - std::cos(hi));
}

// ngan (seed 002 Eq. 1) of a constant difference d of two Lambertians: the outgoing weights of one
// θi sum to 2π, so sqrt(Σ w (d cosθi)² / Σ w) = d · sqrt(Σ_g I_g cos²θ_g / Σ_g I_g) with I_g the
// incidence bands, over the max albedo (the data's own albedos: the rings' midpoint rule of 0.5).
TEST(ScatteredMetric, NganOfAConstantDifferenceUsesTheSamplesPairMeasure) {
  const Model& m = model_by_name("lambert");
  const ParamValues measured = make_values(m, {{"kd", Rgb::Constant(0.5)}});
  const ParamValues fitted = make_values(m, {{"kd", Rgb::Constant(0.3)}});
  const test::ScatteredData data = scattered_model(m, measured);
  const Metric metric = make_metric("ngan", data);
  EXPECT_TRUE(metric.on_samples());
  EXPECT_EQ(metric.sample_count(), size_t(8 * (1 + 9 * 19)));
  double num = 0, den = 0, albedo = 0;
  for (int g = 1; g <= 8; ++g) {
    num += band(g) * std::pow(std::cos(g * 10 * kDeg), 2);
    den += band(g);
  }
  for (const auto& [t, a] : data.albedos_from_samples()) albedo = std::max(albedo, a.maxCoeff());
  const double d = 0.2 / kPi, expected = d * std::sqrt(num / den) / albedo;
  EXPECT_NEAR(metric.value(m, fitted), expected, 1e-12 * expected);
  EXPECT_EQ(metric.value(m, measured), 0.0);
  // bagher (seed 000 §6.3): d (Σ pair measure · cosθi cosθo)^½ / albedo, pair measure = I_g · w.
  const SampleSet s = data.samples();
  double sum = 0;
  for (size_t k = 0; k < s.size(); ++k)
    sum += band(int(std::lround(std::acos(s.wi_z[k]) / (10 * kDeg)))) * s.weight[k] * s.wi_z[k] * s.wo_z[k];
  const double bagher = d * std::sqrt(sum) / albedo;
  EXPECT_NEAR(make_metric("bagher", data).value(m, fitted), bagher, 1e-12 * bagher);
}

// Recovery: exact samples of a known Cook-Torrance GGX are fitted back to its parameters under
// every metric with a linear residual (variable projection) and under low-e2.
TEST(ScatteredMetric, SyntheticScatteredSetIsFittedBackToItsParameters) {
  const Model& m = model_by_name("cook-torrance-ggx");
  const ParamValues want = make_values(m, {{"kd", Rgb(0.12, 0.08, 0.05)},
                                           {"ks", Rgb(0.9, 0.7, 0.6)},
                                           {"alpha", Rgb::Constant(0.25)},
                                           {"F0", Rgb(0.05, 0.04, 0.08)}});
  const test::ScatteredData data = scattered_model(m, want);
  for (const char* id : {"ngan", "bagher", "low-e1", "low-e2", "hp-rmse"}) {
    SCOPED_TRACE(id);
    const Metric metric = make_metric(id, data);
    ASSERT_TRUE(metric.on_samples());
    const FitResult r = fit_model(m, metric, {});
    EXPECT_TRUE(std::isfinite(r.metric_value));
    double worst = 0;  // largest relative parameter error, recorded for the log
    for (const char* name : {"kd", "ks", "alpha", "F0"}) {
      const size_t p = size_t(find_param(m.params(), name));
      for (int c = 0; c < 3; ++c) {
        const double x = want.values[size_t(c)][p], y = r.values.values[size_t(c)][p];
        EXPECT_NEAR(y, x, 1e-3 * x) << name << "[" << c << "]";
        worst = std::max(worst, std::abs(y - x) / x);
      }
    }
    RecordProperty(std::string(id) + "_max_rel_error", testing::PrintToString(worst));
  }
}

// Issue #5: `fit` on every Cornell file succeeds with finite values of every metric.
TEST(ScatteredMetric, CliFitsEveryCornellFileWithFiniteMetrics) {
  BRDFKIT_REQUIRE_DATA("cornell");
  const auto dir = test::scratch_dir("fit_scattered");
  for (const char* file : {"acryl_blue", "garnet_red", "krylon_blue"})
    for (const char* model : {"cook-torrance-ggx", "lambert"}) {
      SCOPED_TRACE(std::string(file) + " " + model);
      const auto out = dir / (std::string(file) + "_" + model + ".json");
      const auto r = test::run_cli("fit " + (test::data_dir() / "cornell" / (std::string(file) + ".brdf")).string() +
                                   " --model " + model + " -o " + out.string());
      ASSERT_EQ(r.exit_code, 0) << r.err;
      std::ifstream in(out);
      const nlohmann::json j = nlohmann::json::parse(in);
      ASSERT_EQ(j.at("metrics").size(), metric_ids().size());
      for (const auto& [id, v] : j.at("metrics").items()) {
        ASSERT_TRUE(v.is_number()) << id;
        EXPECT_TRUE(std::isfinite(v.get<double>()) && v.get<double>() >= 0) << id;
      }
    }
  std::filesystem::remove_all(dir);
}

// The ALTA slice (wi = wo, one sample per θh): its rows are the domain of the metrics that need no
// albedo; ngan and bagher are normalized by an albedo the slice cannot give (MetricUndefined).
TEST(ScatteredMetric, AltaSliceIsMeasuredOnItsRows) {
  BRDFKIT_REQUIRE_DATA("merl-slices");
  const AltaSlice data(test::data_dir() / "merl-slices" / "pink-felt-1d.alta");
  const Model& m = model_by_name("lambert");
  const ParamValues v = make_values(m, {{"kd", Rgb::Constant(0.3)}});
  for (const char* id : {"low-e1", "low-e2", "hp-rmse"}) {
    const Metric metric = make_metric(id, data);
    EXPECT_TRUE(metric.on_samples()) << id;
    EXPECT_GT(metric.sample_count(), 0u) << id;
    const double e = metric.value(m, v);
    EXPECT_TRUE(std::isfinite(e) && e > 0) << id << " " << e;
  }
  EXPECT_THROW(make_metric("ngan", data), MetricUndefined);
}

}  // namespace
}  // namespace brdfkit::fit
