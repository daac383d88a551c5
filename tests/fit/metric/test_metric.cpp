// Metric values against closed forms / independent sums for a constant difference of two
// Lambertian materials (ρ − m = Δkd/π everywhere), on each paper's grid.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>

#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/fit/metric/metric_report.h"
#include "brdfkit/fit/metric/metric_store.h"
#include "brdfkit/models/lambert.h"
#include "support/fit_test_util.h"

namespace brdfkit::fit {
namespace {

using test::AnalyticMeasured;
using test::make_values;

constexpr double kDeg = kPi / 180;

struct LambertPair {
  const Model& model = model_by_name("lambert");
  ParamValues measured = make_values(model, {{"kd", Rgb::Constant(0.5)}});
  ParamValues fitted = make_values(model, {{"kd", Rgb::Constant(0.3)}});
  double d = 0.2 / kPi;  // |ρ − m|
};

// ngan (seed 002 Eq. 1) with w = sinθi sinθo: the θo and Δφ sums cancel, leaving
// d · sqrt(∫ sin cos² / ∫ sin) over θi ∈ [0, 80°] = d · sqrt((1 − cos³80°) / (3 (1 − cos80°))),
// divided by the max albedo 0.5 of the measured Lambertian.
TEST(Metric, NganOfAConstantDifferenceIsClosedForm) {
  LambertPair p;
  const AnalyticMeasured data(p.model, p.measured);
  const Metric m = make_metric("ngan", data);
  EXPECT_EQ(m.sample_count(), size_t(80 * 80 * 180));
  // Midpoint rule over 1° cells of ∫ (0.5/π) cosθo dωo = 0.5 Σ sin 2θo Δθ (≈ 0.5 (1 + 5.1e-5)).
  double albedo = 0;
  for (int b = 0; b < 90; ++b) albedo += 0.5 * std::sin(2 * (b + 0.5) * kDeg) * kDeg;
  EXPECT_NEAR(m.albedo_norm(), albedo, 1e-12);
  EXPECT_NEAR(albedo, 0.5, 0.5 * 6e-5);
  const double c = std::cos(80 * kDeg);
  const double expected = p.d * std::sqrt((1 - c * c * c) / (3 * (1 - c))) / albedo;
  const double got = m.value(p.model, p.fitted);
  EXPECT_NEAR(got, expected, expected * 1e-4) << got << " vs " << expected;
  EXPECT_EQ(m.value(p.model, p.measured), 0.0);
}

// A Lambertian measured only for θi ≤ 40° (θo over the whole hemisphere): the domain is no longer
// symmetric in θi and θo, so the cosθi factor of Eq. 1 is told apart from a cosθo one.
class MeasuredBelowIncidence final : public MeasuredBrdf {
 public:
  MeasuredBelowIncidence(const Model& model, ParamValues values, double max_theta_i)
      : brdf_(model, std::move(values)), min_cos_i_(std::cos(max_theta_i)) {}
  std::string format() const override { return "analytic"; }
  std::string path() const override { return "analytic:lambert, theta_i <= 40 deg"; }
  std::string dimensions() const override { return "continuous"; }
  std::optional<Rgb> eval(const Vec3d& wi, const Vec3d& wo) const override {
    if (!(wi.z() >= min_cos_i_ && wo.z() > 0)) return std::nullopt;
    return brdf_.eval(wi, wo);
  }
  SampleSet samples() const override { return {}; }

 private:
  Brdf brdf_;
  double min_cos_i_;
};

// ngan on that domain: the θi sum stops at 40° while the θo sum still runs to 80°, so
// E = d · sqrt((1 − c³)/(3 (1 − c))) with c = cos 40° (the θi bound), over the max albedo, which
// the rows θi ≤ 40° still reach (θo covers the hemisphere). With cosθo in place of cosθi the
// bound would be θo's 80° instead: 0.633 d against 0.886 d here.
TEST(Metric, NganOnADomainAsymmetricInThetaIAndThetaO) {
  LambertPair p;
  const MeasuredBelowIncidence data(p.model, p.measured, 40 * kDeg);
  const Metric m = make_metric("ngan", data);
  EXPECT_EQ(m.sample_count(), size_t(40 * 80 * 180));
  double albedo = 0;
  for (int b = 0; b < 90; ++b) albedo += 0.5 * std::sin(2 * (b + 0.5) * kDeg) * kDeg;
  EXPECT_NEAR(m.albedo_norm(), albedo, 1e-12);
  const double c = std::cos(40 * kDeg);
  const double expected = p.d * std::sqrt((1 - c * c * c) / (3 * (1 - c))) / albedo;
  const double got = m.value(p.model, p.fitted);
  std::printf("ngan, theta_i <= 40 deg: %.8g, closed form %.8g\n", got, expected);
  EXPECT_NEAR(got, expected, expected * 1e-4) << got << " vs " << expected;
}

// The same through a MERL-format table (constant: the look-up is exact).
TEST(Metric, NganOnATabulatedMerlTableMatchesTheAnalyticData) {
  LambertPair p;
  const MerlBrdf merl(test::tabulate_model(p.model, p.measured), "lambert.binary");
  const AnalyticMeasured analytic(p.model, p.measured);
  // The grid looked up in the nearest cell: a constant difference is the same at every point.
  const double a = make_metric("ngan", merl, {2, MetricDomain::Grid}).value(p.model, p.fitted);
  const double b = make_metric("ngan", analytic, {2}).value(p.model, p.fitted);
  EXPECT_NEAR(a, b, 1e-12 * b);
}

// bagher (seed 000 §6.3): d · (∫∫ cosθi cosθo dωi dωo)^½ = d π, over the max albedo.
TEST(Metric, BagherOfAConstantDifferenceIsClosedForm) {
  LambertPair p;
  const AnalyticMeasured data(p.model, p.measured);
  const Metric m = make_metric("bagher", data);
  const double expected = p.d * kPi / 0.5;
  EXPECT_NEAR(m.albedo_norm(), 0.5, 0.5 * 6e-5);
  EXPECT_NEAR(m.value(p.model, p.fitted), expected, expected * 1e-4);
}

// low-e1/e2 (seed 003 Eq. 29–33): Σ over θi = 0…80° (10°), θo = 0…80° and φo = 0…359° (1°)
// of (g − ĝ)² sinθo Δφ Δθo Δθi, channels summed; computed here as the nested sum.
TEST(Metric, LowE1AndE2MatchTheirSums) {
  LambertPair p;
  const AnalyticMeasured data(p.model, p.measured);
  double so = 0;
  for (int o = 0; o <= 80; ++o) so += std::sin(o * kDeg) * kDeg;
  double e1 = 0, e2 = 0;
  for (int i = 0; i <= 80; i += 10) {
    const double ci = std::cos(i * kDeg);
    e1 += std::pow(ci * p.d, 2) * 10 * kDeg;
    e2 += std::pow(std::log1p(ci * 0.5 / kPi) - std::log1p(ci * 0.3 / kPi), 2) * 10 * kDeg;
  }
  e1 *= 3 * so * 360 * kDeg;
  e2 *= 3 * so * 360 * kDeg;
  EXPECT_NEAR(make_metric("low-e1", data).value(p.model, p.fitted), e1, e1 * 1e-12);
  EXPECT_NEAR(make_metric("low-e2", data).value(p.model, p.fitted), e2, e2 * 1e-12);
}

// hp-rmse (seed 004 Eq. 31), on a grid coarsened 4× (θi every 4°, θo and φo every 1°).
TEST(Metric, HpRmseMatchesItsSum) {
  LambertPair p;
  const AnalyticMeasured data(p.model, p.measured);
  double so = 0, si = 0;
  for (int o = 0; o <= 80; ++o) so += std::sin(o * kDeg) * kDeg;
  for (int i = 0; i <= 80; i += 4) si += std::pow(std::cos(i * kDeg), 2) * 4 * kDeg;
  const double expected = p.d * std::sqrt(si * so * 360 * kDeg);
  EXPECT_NEAR(make_metric("hp-rmse", data, {4}).value(p.model, p.fitted), expected, expected * 1e-12);
}

// GGX data from known parameters, and another parameter set to evaluate metrics at.
struct GgxData {
  const Model& ggx = model_by_name("cook-torrance-ggx");
  const ParamValues truth =
      make_values(ggx, {{"kd", Rgb(0.1, 0.2, 0.3)}, {"ks", Rgb(0.8, 0.6, 0.5)}, {"alpha", Rgb::Constant(0.2)}});
  const ParamValues other =
      make_values(ggx, {{"kd", Rgb(0.12, 0.2, 0.25)}, {"ks", Rgb(0.7, 0.6, 0.6)}, {"alpha", Rgb::Constant(0.25)}});
  const AnalyticMeasured data{ggx, truth};
};

// A metric only reported (MetricOptions::keep = false) looks its grid up again at each value():
// the kept metric's number to the last bit, nothing kept, the same refusal of an empty domain,
// and a store entry of its own (a fit under the kept one must not get it).
TEST(Metric, AGridNotKeptGivesTheKeptValue) {
  const GgxData g;
  const Model& ggx = g.ggx;
  const ParamValues& other = g.other;
  const AnalyticMeasured& data = g.data;
  MetricOptions kept{2}, dropped{2};
  dropped.keep = false;
  for (const char* id : {"ngan", "bagher", "low-e1", "low-e2"}) {
    const Metric a = make_metric(id, data, kept), b = make_metric(id, data, dropped);
    EXPECT_TRUE(a.cached()) << id;
    EXPECT_FALSE(b.cached()) << id;
    EXPECT_EQ(a.value(ggx, other), b.value(ggx, other)) << id;
    EXPECT_GT(a.value(ggx, other), 0.0) << id;
  }
  MetricStore store(data);
  EXPECT_NE(store.metric("bagher", kept), store.metric("bagher", dropped));
  EXPECT_EQ(store.metric("bagher", dropped), store.metric("bagher", dropped));
  EXPECT_TRUE(store.metric("bagher", kept)->cached());
  const MerlBrdf empty(merl::Table(), "empty.binary");
  dropped.coarsen = 4;
  dropped.domain = MetricDomain::Grid;  // the grid, looked up in a table without a cell
  EXPECT_THROW(make_metric("ngan", empty, dropped), MetricUndefined);
}

// A fit's report keeps the samples of the metric it fitted under (the store holds them already)
// and evaluates every other metric chunk by chunk, nothing kept: the values of a report that keeps
// every domain, to the last bit.
TEST(Metric, AFitsReportKeepsOnlyTheFittedMetric) {
  const GgxData g;
  const Model& ggx = g.ggx;
  const ParamValues& other = g.other;
  const AnalyticMeasured& data = g.data;
  const std::vector<std::string> ids = {"ngan", "bagher", "low-e1"};
  const MetricOptions kept{2};
  MetricOptions dropped{2};
  dropped.keep = false;
  MetricStore fitted(data), every(data);
  fitted.metric("ngan", kept);  // the fit's
  const std::vector<MetricReport> a = report_metrics(fitted, ggx, other, ids, kept, "ngan");
  const std::vector<MetricReport> b = report_metrics(every, ggx, other, ids, kept);
  ASSERT_EQ(a.size(), ids.size());
  for (size_t i = 0; i < ids.size(); ++i) {
    ASSERT_TRUE(a[i].value && b[i].value) << ids[i];
    EXPECT_EQ(*a[i].value, *b[i].value) << ids[i];
    EXPECT_TRUE(every.holds(ids[i], kept)) << ids[i];
  }
  EXPECT_FALSE(fitted.holds("ngan", dropped));
  for (const char* id : {"bagher", "low-e1"}) {
    EXPECT_FALSE(fitted.holds(id, kept)) << id;
    EXPECT_TRUE(fitted.holds(id, dropped)) << id;
  }
}

TEST(Metric, UnknownIdAndEmptyDomainAreInputErrors) {
  LambertPair p;
  const AnalyticMeasured data(p.model, p.measured);
  EXPECT_THROW(make_metric("rmse", data), InputError);
  EXPECT_THROW(make_metric("ngan", data, {0}), InputError);
  // A table with no measured cell: nothing to compare.
  const MerlBrdf empty(merl::Table(), "empty.binary");
  EXPECT_THROW(make_metric("ngan", empty, {4}), MetricUndefined);
}

}  // namespace
}  // namespace brdfkit::fit
