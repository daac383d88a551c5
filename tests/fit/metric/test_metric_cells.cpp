// The metrics on a MERL table's own cells (fit/metric_cells.h) approximate each paper's integral:
// for a constant difference of two Lambertian materials (ρ − m = Δkd/π everywhere) the integrals
// have closed forms; the cell rule differs from them only where the domain's edge (θ = 80°, the
// horizon) cuts through cells.
#include <gtest/gtest.h>

#include <cmath>

#include "brdfkit/fit/metric/metric.h"
#include "support/merl_cases.h"

namespace brdfkit::fit {
namespace {

constexpr double kDeg = kPi / 180;

struct LambertPair {
  const Model& model = model_by_name("lambert");
  ParamValues measured = test::with(model, {{"kd", Rgb::Constant(0.5)}});
  ParamValues fitted = test::with(model, {{"kd", Rgb::Constant(0.3)}});
  double d = 0.2 / kPi;  // |ρ − m|
  MerlBrdf data{test::tabulate_cells(model, measured, 1), "lambert.binary"};
};

// ngan: d · sqrt(∫∫ cos²θi dωi dωo / ∫∫ dωi dωo) over θi, θo ≤ 80° = d · sqrt((1 − c³)/(3 (1 − c))),
// c = cos 80°, over the max albedo 0.5.
TEST(MetricCells, NganOfAConstantDifferenceIsTheIntegral) {
  LambertPair p;
  const Metric m = make_metric("ngan", p.data);
  ASSERT_TRUE(m.on_cells());
  const double c = std::cos(80 * kDeg);
  const double expected = p.d * std::sqrt((1 - c * c * c) / (3 * (1 - c))) / m.albedo_norm();
  const double got = m.value(p.model, p.fitted);
  std::printf("ngan on cells %.8g, integral %.8g (%zu cells)\n", got, expected, m.sample_count());
  EXPECT_NEAR(got, expected, 2e-3 * expected);
  EXPECT_EQ(m.value(p.model, p.measured), 0.0);
  // The paper's grid stays available (MetricDomain::Grid) and agrees to its own quadrature error.
  const Metric grid = make_metric("ngan", p.data, {1, MetricDomain::Grid});
  EXPECT_FALSE(grid.on_cells());
  EXPECT_NEAR(grid.value(p.model, p.fitted), expected, 2e-3 * expected);
}

// bagher: d · (∫∫ cosθi cosθo dωi dωo)^½ = d π over the max albedo.
TEST(MetricCells, BagherOfAConstantDifferenceIsTheIntegral) {
  LambertPair p;
  const Metric m = make_metric("bagher", p.data);
  ASSERT_TRUE(m.on_cells());
  const double expected = p.d * kPi / m.albedo_norm();
  const double got = m.value(p.model, p.fitted);
  std::printf("bagher on cells %.8g, integral %.8g\n", got, expected);
  EXPECT_NEAR(got, expected, 2e-3 * expected);
}

// low-e1: Σ_c ∫₀^{80°} dθi ∫_{θo ≤ 80°} (cosθi d)² dωo = 3 d² ∫₀^{80°} cos²θi dθi · 2π (1 − cos 80°)
// (seed 003 Eq. 33's integral); low-e2 likewise with (ln(1 + cosθi m) − ln(1 + cosθi ρ))², by
// a fine midpoint rule in θi.
TEST(MetricCells, LowE1AndE2AreTheirIntegrals) {
  LambertPair p;
  const double c80 = std::cos(80 * kDeg), top = 80 * kDeg;
  double i1 = 0, i2 = 0;
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    const double t = (k + 0.5) / n * top, ci = std::cos(t);
    i1 += std::pow(ci * p.d, 2) * top / n;
    i2 += std::pow(std::log1p(ci * 0.5 / kPi) - std::log1p(ci * 0.3 / kPi), 2) * top / n;
  }
  const double ring = 2 * kPi * (1 - c80);
  const double e1 = 3 * i1 * ring, e2 = 3 * i2 * ring;
  const double g1 = make_metric("low-e1", p.data).value(p.model, p.fitted);
  const double g2 = make_metric("low-e2", p.data).value(p.model, p.fitted);
  std::printf("low-e1 on cells %.8g, integral %.8g; low-e2 %.8g, %.8g\n", g1, e1, g2, e2);
  EXPECT_NEAR(g1, e1, 1e-2 * e1);
  EXPECT_NEAR(g2, e2, 1e-2 * e2);
}

// hp-rmse: d · (∫₀^{1.4} cos²θi dθi · ∫_{θo < 1.4} dωo)^½ = d · (0.7 + sin(2.8)/4)^½ (2π (1 − cos 1.4))^½
// (seed 004 Eq. 31, channels averaged). On cells its weight 1/(2π sinθi) is largest near the
// pole, where the centre rule is least exact.
TEST(MetricCells, HpRmseOfAConstantDifferenceIsTheIntegral) {
  LambertPair p;
  const Metric m = make_metric("hp-rmse", p.data);
  ASSERT_TRUE(m.on_cells());
  const double expected = p.d * std::sqrt((0.7 + std::sin(2.8) / 4) * 2 * kPi * (1 - std::cos(1.4)));
  const double got = m.value(p.model, p.fitted);
  std::printf("hp-rmse on cells %.8g, integral %.8g\n", got, expected);
  EXPECT_NEAR(got, expected, 2e-3 * expected);
  EXPECT_EQ(m.value(p.model, p.measured), 0.0);
}

// A cells domain only reported (MetricOptions::keep = false) is built again chunk by chunk at
// each value(): the kept domain's number to the last bit, for folded and unfolded cells and for
// ngan's division by Σ w; an empty table is refused as when kept.
TEST(MetricCells, CellsNotKeptGiveTheKeptValue) {
  LambertPair p;
  MetricOptions kept{2}, dropped{2};
  dropped.keep = false;
  for (const char* id : {"ngan", "bagher", "low-e1", "low-e2", "hp-rmse"}) {
    const Metric a = make_metric(id, p.data, kept), b = make_metric(id, p.data, dropped);
    ASSERT_TRUE(a.on_cells() && b.on_cells()) << id;
    EXPECT_TRUE(a.cached()) << id;
    EXPECT_FALSE(b.cached()) << id;
    EXPECT_EQ(a.value(p.model, p.fitted), b.value(p.model, p.fitted)) << id;
    EXPECT_GT(a.value(p.model, p.fitted), 0.0) << id;
  }
  const MerlBrdf empty(merl::Table(), "empty.binary");
  EXPECT_THROW(make_metric("hp-rmse", empty, dropped), MetricUndefined);
  EXPECT_THROW(make_metric("hp-rmse", empty, kept), MetricUndefined);
}

}  // namespace
}  // namespace brdfkit::fit
