// The metrics of DESIGN.md §7 take θi as the illumination direction: the measured value is
// looked up at (wi, wo), and the seeds' cosine factor (ngan, low-e1/e2, hp-rmse compare cosθi ρ)
// is the cosine of wi. Data and model here are functions of θi alone (non_reciprocal_fixtures.h),
// with cosθi (ρ − m) = k exactly, so each metric has a closed-form value computed from its
// definition (DESIGN.md §7 and the paper it cites) — and a different one if the cosine were
// cosθo or the look-up were made at (wo, wi), which each test also computes and shows apart.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "brdfkit/fit/metric/metric.h"
#include "non_reciprocal_fixtures.h"

namespace brdfkit::test {
namespace {

constexpr double kDeg = kPi / 180;
constexpr double kK = 0.03;

struct Case {
  std::string id;
  int coarsen;
  bool cos_i_factor;
};
const std::vector<Case> kCases = {
    {"ngan", 1, true}, {"low-e1", 1, true}, {"low-e2", 1, true}, {"hp-rmse", 4, true}, {"bagher", 1, false}};

ParamValues k_values(const Model& m, double k) {
  ParamValues v = ParamValues::defaults(m.params());
  v.set(m.params(), "k", k);
  return v;
}

// Every sample of every chunk: the factor is cosθi of the sample's wi (or 1), the measured value
// is data(wi, wo) — and the domain has many samples with θi far from θo, where a swap would show.
TEST(MetricConvention, SamplesTakeTheFactorAndTheLookUpFromWi) {
  const IncidenceOnlyData data;
  for (const Case& mc : kCases) {
    fit::MetricOptions opt;
    opt.coarsen = mc.coarsen;
    const fit::Metric metric = fit::make_metric(mc.id, data, opt);
    size_t samples = 0, distinct = 0, factor_errors = 0, lookup_errors = 0;
    for (size_t i = 0; i < metric.chunk_count(); ++i) {
      fit::MetricChunk scratch;
      const fit::MetricChunk& ch = metric.chunk(i, scratch);
      for (size_t k = 0; k < ch.size(); ++k) {
        const Vec3d wi(ch.wi_x[k], ch.wi_y[k], ch.wi_z[k]), wo(ch.wo_x[k], ch.wo_y[k], ch.wo_z[k]);
        if (ch.factor[k] != (mc.cos_i_factor ? wi.z() : 1.0)) ++factor_errors;
        const Rgb m = *data.eval(wi, wo);
        for (int c = 0; c < 3; ++c)
          if (ch.measured[size_t(c)][k] != m[c]) ++lookup_errors;
        if (std::abs(wi.z() - wo.z()) > 0.2) ++distinct;
        ++samples;
      }
    }
    EXPECT_EQ(factor_errors, 0u) << mc.id << ": samples whose factor is not cos(theta_i)";
    EXPECT_EQ(lookup_errors, 0u) << mc.id << ": samples whose measured value is not data(wi, wo)";
    EXPECT_GT(distinct, samples / 4) << mc.id;
    std::printf("[ convention ] %-8s %zu samples, %zu with |cos(theta_i) - cos(theta_o)| > 0.2\n", mc.id.c_str(), samples,
                distinct);
  }
}

// Σ over the domain of w · f(cosθi, cosθo), with the samples' own weights (ngan's w = sinθi sinθo
// and bagher's are checked against their definitions below; low and hp grids are recomputed
// independently in the tests that use them).
template <class F> double weighted_sum(const fit::Metric& metric, F f) {
  double s = 0;
  for (size_t i = 0; i < metric.chunk_count(); ++i) {
    fit::MetricChunk scratch;
    const fit::MetricChunk& ch = metric.chunk(i, scratch);
    for (size_t k = 0; k < ch.size(); ++k) s += ch.sqrt_weight[k] * ch.sqrt_weight[k] * f(ch.wi_z[k], ch.wo_z[k]);
  }
  return s;
}

// seed 002 Eq. 1: sqrt(Σ w (cosθi ρ − cosθi m)² / Σ w) = k, over the max albedo.
TEST(MetricConvention, NganComparesCosThetaITimesRho) {
  const IncidenceOnlyData data;
  const IncidenceOnlyModel model;
  const fit::Metric metric = fit::make_metric("ngan", data);
  const double value = metric.value(model, k_values(model, kK));
  EXPECT_NEAR(value * metric.albedo_norm(), kK, 1e-12 * kK);
  // With cosθo as the factor: sqrt(Σ w k² cos²θo/cos²θi / Σ w).
  const double swapped = kK * std::sqrt(weighted_sum(metric, [](double ci, double co) { return co * co / (ci * ci); }) /
                                        weighted_sum(metric, [](double, double) { return 1.0; }));
  std::printf("[ convention ] ngan x albedo: %.6g (k = %g); with cos(theta_o) it would be %.6g\n",
              value * metric.albedo_norm(), kK, swapped);
  EXPECT_GT(std::abs(swapped / kK - 1), 0.5);
}

// The normalizing albedo is the measured one with θi the illumination direction:
// a(θi) = ∫ m(wi, wo) cosθo dωo = π (a + b/cosθi), largest at the last θi cell centre (79.5°).
// Taken the other way, ∫ m(wo, wi) cosθo dωo = π a + 2π b.
TEST(MetricConvention, NganAlbedoIsIntegratedOverWo) {
  const IncidenceOnlyData data;
  const fit::Metric metric = fit::make_metric("ngan", data);
  const double expected = kPi * (kIncidenceA[0] + kIncidenceB / std::cos(79.5 * kDeg));
  const double swapped = kPi * kIncidenceA[0] + 2 * kPi * kIncidenceB;
  EXPECT_NEAR(metric.albedo_norm(), expected, 2e-3 * expected);
  EXPECT_GT(std::abs(swapped / expected - 1), 0.1);
}

// seed 003 Eq. 29–33: E1 = Σ (cosθi ρ − cosθi m)² sinθo Δφo Δθo Δθi, channels summed, θi every 10°,
// θo and φo every 1°, θ ≤ 80°: here 3 k² Σ w with Σ w = (9 · 10°) (Σ_{j=1}^{80} sin j° · 1°) (2π).
TEST(MetricConvention, LowE1ComparesCosThetaITimesRho) {
  const IncidenceOnlyData data;
  const IncidenceOnlyModel model;
  const fit::Metric metric = fit::make_metric("low-e1", data);
  double sin_sum = 0;
  for (int j = 1; j <= 80; ++j) sin_sum += std::sin(j * kDeg) * kDeg;
  const double w = 9 * (10 * kDeg) * sin_sum * (2 * kPi);
  const double value = metric.value(model, k_values(model, kK));
  EXPECT_NEAR(value, 3 * kK * kK * w, 1e-11 * value);
  const double swapped = 3 * kK * kK * weighted_sum(metric, [](double ci, double co) { return co * co / (ci * ci); });
  std::printf("[ convention ] low-e1: %.6g (expected %.6g); with cos(theta_o) it would be %.6g\n", value,
              3 * kK * kK * w, swapped);
  EXPECT_GT(std::abs(swapped / value - 1), 0.5);
}

// E2: the same sum of (ln(1 + cosθi ρ) − ln(1 + cosθi m))², which is not a function of k alone:
// computed here node by node from the grid of seed 003 §5.1.
TEST(MetricConvention, LowE2ComparesLogOfCosThetaITimesRho) {
  const IncidenceOnlyData data;
  const IncidenceOnlyModel model;
  const fit::Metric metric = fit::make_metric("low-e2", data);
  auto e2 = [](bool cos_of_wo) {
    double sum = 0;
    for (int i = 0; i <= 8; ++i)
      for (int o = 1; o <= 80; ++o) {
        const double ci = std::cos(10 * i * kDeg), co = std::cos(o * kDeg), f = cos_of_wo ? co : ci;
        const double w = (10 * kDeg) * std::sin(o * kDeg) * kDeg * (2 * kPi);
        for (int c = 0; c < 3; ++c) {
          const double m = kIncidenceA[size_t(c)] + kIncidenceB / ci, rho = m + kK / ci;
          sum += w * std::pow(std::log1p(f * rho) - std::log1p(f * m), 2);
        }
      }
    return sum;
  };
  const double value = metric.value(model, k_values(model, kK));
  EXPECT_NEAR(value, e2(false), 1e-10 * value);
  std::printf("[ convention ] low-e2: %.6g (expected %.6g); with cos(theta_o) it would be %.6g\n", value, e2(false),
              e2(true));
  EXPECT_GT(std::abs(e2(true) / value - 1), 0.5);
}

// seed 004 Eq. 31: [∫ (ρM − ρE)² cos²θi dωo dθi]^{1/2}, channels averaged; grid widened 4× in θi
// (MetricOptions::coarsen, for speed): θi = 0°, 4°, …, 80°, θo and φo every 1°, θ < 1.4 rad. Here
// k sqrt(Σ w), Σ w = (21 · 4°) (Σ_{j=1}^{80} sin j° · 1°) (2π).
TEST(MetricConvention, HpRmseWeightsByCosSquaredThetaI) {
  const IncidenceOnlyData data;
  const IncidenceOnlyModel model;
  fit::MetricOptions opt;
  opt.coarsen = 4;
  const fit::Metric metric = fit::make_metric("hp-rmse", data, opt);
  double sin_sum = 0;
  for (int j = 1; j <= 80; ++j) sin_sum += std::sin(j * kDeg) * kDeg;
  const double w = 21 * (4 * kDeg) * sin_sum * (2 * kPi);
  const double value = metric.value(model, k_values(model, kK));
  EXPECT_NEAR(value, kK * std::sqrt(w), 1e-11 * value);
  const double swapped = kK * std::sqrt(weighted_sum(metric, [](double ci, double co) { return co * co / (ci * ci); }));
  std::printf("[ convention ] hp-rmse: %.6g (expected %.6g); with cos(theta_o) it would be %.6g\n", value,
              kK * std::sqrt(w), swapped);
  EXPECT_GT(std::abs(swapped / value - 1), 0.2);
}

// seed 000 §6.3: (∫∫ (m − ρ)² cosθi cosθo dωi dωo)^{1/2}, channels averaged, over the max albedo,
// no cosine factor: with ρ − m = k/cosθi, value · albedo = k sqrt(Σ_i 2π sinθi/cosθi Δθ ·
// Σ_o sinθo cosθo Δθ · 2π), 1° cell centres up to 89.5°. Its weight is symmetric in θi and θo,
// so this value is the same with the roles swapped: the sample check above pins bagher's roles.
TEST(MetricConvention, BagherValueFromItsDefinition) {
  const IncidenceOnlyData data;
  const IncidenceOnlyModel model;
  const fit::Metric metric = fit::make_metric("bagher", data);
  double si = 0, so = 0;
  for (int j = 0; j < 90; ++j) {
    const double t = (j + 0.5) * kDeg;
    si += 2 * kPi * std::sin(t) / std::cos(t) * kDeg;
    so += std::sin(t) * std::cos(t) * kDeg;
  }
  const double expected = kK * std::sqrt(si * so * 2 * kPi);
  EXPECT_NEAR(metric.value(model, k_values(model, kK)) * metric.albedo_norm(), expected, 1e-10 * expected);
}

}  // namespace
}  // namespace brdfkit::test
