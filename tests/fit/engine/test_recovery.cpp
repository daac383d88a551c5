// Recovery: materials tabulated from known parameters are fitted back from the default start
// (DESIGN.md §8 `ngan` procedure: projected colours, bounded Ceres for the shape).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "brdfkit/fit/engine/fit_model.h"
#include "support/fit_test_util.h"

namespace brdfkit::fit {
namespace {

using test::make_values;

ParamValues truth(const Model& m, double alpha) {
  return make_values(m, {{"kd", Rgb(0.12, 0.08, 0.05)},
                         {"ks", Rgb(0.9, 0.7, 0.6)},
                         {"alpha", Rgb::Constant(alpha)},
                         {"F0", Rgb(0.05, 0.04, 0.08)}});
}

double param(const Model& m, const ParamValues& v, const char* name, int c = 0) {
  return v.values[size_t(c)][size_t(find_param(m.params(), name))];
}

void expect_recovered(const Model& m, const ParamValues& want, const ParamValues& got, double tol_shape,
                      double tol_colour) {
  const double a = param(m, want, "alpha"), b = param(m, got, "alpha");
  EXPECT_NEAR(b, a, tol_shape * a) << "alpha";
  for (int c = 0; c < 3; ++c)
    for (const char* name : {"kd", "ks", "F0"}) {
      const double x = param(m, want, name, c), y = param(m, got, name, c);
      // F0 rides on the Fresnel tail near grazing, where the table's quantization weighs most.
      const double tol = std::string(name) == "F0" ? 2 * tol_colour : tol_colour;
      EXPECT_NEAR(y, x, tol * x) << name << "[" << c << "]";
    }
}

// Exact values anywhere (no table quantization): the fit must reach the truth to solver
// precision, for both distributions.
TEST(Recovery, AnalyticCookTorranceBeckmannAndGgxUnderNgan) {
  for (const char* name : {"cook-torrance-beckmann", "cook-torrance-ggx"}) {
    const Model& m = model_by_name(name);
    const ParamValues want = truth(m, 0.12);
    const test::AnalyticMeasured data(m, want);
    const Metric metric = make_metric("ngan", data, {2});
    const FitResult r = fit_model(m, metric, {});
    SCOPED_TRACE(name);
    expect_recovered(m, want, r.values, 1e-6, 1e-5);
    EXPECT_LT(r.metric_value, 1e-7);
  }
}

// MERL-format tables: the metric's domain is the table's own cells (fit/metric_cells.h), where
// the values are exact, so the optimum is the truth (tests/fit_merl/ covers every single-lobe
// model). The paper's (θi, θo, Δφ) grid looked up in the nearest cell (MetricDomain::Grid) instead
// compares the model at a grid point with the value at the cell centre, a quantization that
// biases the optimum itself (measured on the full grid, α = 0.12: Beckmann α +0.72 %, GGX +0.84 %,
// ks −4 … −5 %, F0 +5 … +6 %): checked below to be still there, as the reason for the cells.
TEST(Recovery, MerlTabulatedCookTorranceBeckmannAndGgx) {
  for (const char* name : {"cook-torrance-beckmann", "cook-torrance-ggx"}) {
    const Model& m = model_by_name(name);
    const ParamValues want = truth(m, 0.12);
    const MerlBrdf data(test::tabulate_model(m, want), "ct.binary");
    const FitResult r = fit_model(m, make_metric("ngan", data, {2}), {});
    SCOPED_TRACE(name);
    std::printf("%s: alpha %.8g (true 0.12), ngan %.3g, %d iterations\n", name, param(m, r.values, "alpha"),
                r.metric_value, r.iterations);
    expect_recovered(m, want, r.values, 1e-6, 1e-6);
  }
}

TEST(Recovery, MerlGridDomainKeepsTheNearestCellBias) {
  const Model& m = model_by_name("cook-torrance-beckmann");
  const ParamValues want = truth(m, 0.12);
  const MerlBrdf data(test::tabulate_model(m, want), "ct.binary");
  const FitResult r = fit_model(m, make_metric("ngan", data, {2, MetricDomain::Grid}), {});
  const double alpha = param(m, r.values, "alpha");
  std::printf("grid domain: alpha %.6g (true 0.12)\n", alpha);
  EXPECT_GT(std::abs(alpha / 0.12 - 1), 3e-3);
}

TEST(Recovery, MerlTabulatedWithMissingCells) {
  const Model& m = model_by_name("cook-torrance-ggx");
  const ParamValues want = truth(m, 0.2);
  const MerlBrdf data(test::tabulate_model(m, want, 0.3), "ct-missing.binary");
  const FitResult r = fit_model(m, make_metric("ngan", data, {2}), {});
  std::printf("30 %% missing: alpha %.8g (true 0.2)\n", param(m, r.values, "alpha"));
  expect_recovered(m, want, r.values, 1e-6, 1e-6);
}

// 1 % multiplicative noise on every cell read (~110 000 on the coarsened cells): the spread it
// causes is ~1e-4 in α; the bounds are 1e-3 on α, 1e-2 on the colours.
TEST(Recovery, MerlTabulatedWithOnePercentNoise) {
  const Model& m = model_by_name("cook-torrance-beckmann");
  const ParamValues want = truth(m, 0.2);
  const MerlBrdf data(test::tabulate_model(m, want, 0.1, 0.01), "ct-noise.binary");
  const FitResult r = fit_model(m, make_metric("ngan", data, {2}), {});
  std::printf("1 %% noise, 10 %% missing: alpha %.8g (true 0.2)\n", param(m, r.values, "alpha"));
  expect_recovered(m, want, r.values, 1e-3, 1e-2);
}

// Lambert alone: only colours, solved directly by the projection.
TEST(Recovery, LambertColoursAreProjectedExactly) {
  const Model& m = model_by_name("lambert");
  const ParamValues want = make_values(m, {{"kd", Rgb(0.2, 0.5, 0.7)}});
  const MerlBrdf data(test::tabulate_model(m, want), "lambert.binary");
  const FitResult r = fit_model(m, make_metric("ngan", data, {4}), {});
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(param(m, r.values, "kd", c), want.values[size_t(c)][0], 1e-12);
}

// Löw's logarithmic E2 is not linear in the colours: every parameter goes to the solver.
TEST(Recovery, LowE2FitsAllParametersAtOnce) {
  const Model& m = model_by_name("cook-torrance-ggx");
  const ParamValues want = truth(m, 0.2);
  const test::AnalyticMeasured data(m, want);
  const FitResult r = fit_model(m, make_metric("low-e2", data, {2}), {});
  expect_recovered(m, want, r.values, 1e-4, 1e-3);
}

TEST(Recovery, MultiStartIsDeterministicAndNeverWorseThanOneStart) {
  const Model& m = model_by_name("cook-torrance-beckmann");
  const ParamValues want = truth(m, 0.3);
  const test::AnalyticMeasured data(m, want);
  const Metric metric = make_metric("ngan", data, {4});
  const FitResult one = fit_model(m, metric, FitSettings{.starts = 1, .seed = 5});
  const FitResult a = fit_model(m, metric, FitSettings{.starts = 3, .seed = 5});
  const FitResult b = fit_model(m, metric, FitSettings{.starts = 3, .seed = 5});
  EXPECT_EQ(a.values.values, b.values.values);
  EXPECT_EQ(a.metric_value, b.metric_value);
  EXPECT_LE(a.metric_value, one.metric_value);
}

TEST(Recovery, ReportOnlyMetricAndBadOptionsAreInputErrors) {
  const Model& m = model_by_name("lambert");
  const test::AnalyticMeasured data(m, ParamValues::defaults(m.params()));
  EXPECT_THROW(fit_model(m, make_metric("hp-rmse", data, {8}), {}), InputError);
  EXPECT_THROW(fit_model(m, make_metric("ngan", data, {8}), FitSettings{.starts = 0}), InputError);
}

}  // namespace
}  // namespace brdfkit::fit
