// Tabulated-NDF estimation (seed 002 §5.1) on a synthetic MERL-format material with known D.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>

#include "brdfkit/analysis/ndf_estimation.h"
#include "brdfkit/analysis/projected_area_masking.h"
#include "brdfkit/core/turned_frame.h"
#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/measured/merl_brdf.h"
#include "brdfkit/measured/merl_tabulate.h"
#include "brdfkit/measured/sample_set.h"
#include "brdfkit/models/model.h"
#include "brdfkit/ndf/beckmann.h"
#include "brdfkit/ndf/ggx.h"
#include "brdfkit/ndf/ggx_anisotropic.h"
#include "brdfkit/shadowing/smith.h"

namespace brdfkit {
namespace {

// kd = (0.1, 0.08, 0.05), ks = (1, 0.9, 0.7), GGX α = 0.2, Schlick F0 = 0.05: the material the
// acceptance test tabulates.
const double kParams[3][4] = {{0.1, 1.0, 0.2, 0.05}, {0.08, 0.9, 0.2, 0.05}, {0.05, 0.7, 0.2, 0.05}};

const MerlBrdf& synthetic_ggx() {
  static const MerlBrdf brdf(merl::tabulate([](const Vec3d& wi, const Vec3d& wo) {
                               Rgb v;
                               for (int c = 0; c < 3; ++c) v[c] = model_by_name("cook-torrance-ggx").eval(kParams[c], c, wi, wo);
                               return v;
                             }),
                             "synthetic-ggx-0.2");
  return brdf;
}

TEST(ProjectedAreaMasking, MatchesClosedFormSmithForGgxAndBeckmann) {
  const double alpha = 0.2;
  const Ggx<double> ggx(&alpha);
  const Beckmann<double> beck(&alpha);
  const analysis::ProjectedAreaMasking mg([&](double c) { return ggx.D(c); }, {}, 181);
  const analysis::ProjectedAreaMasking mb([&](double c) { return beck.D(c); }, {}, 181);
  double worst = 0;
  for (double deg = 0; deg <= 85; deg += 2.5) {
    const double c = std::cos(deg * kPi / 180);
    worst = std::max(worst, std::abs(mg.g1(c) - smith_g1(ggx, c)));
    worst = std::max(worst, std::abs(mb.g1(c) - smith_g1(beck, c)));
  }
  std::printf("max |G1 projected-area - closed form| over 0..85 deg: %.2e\n", worst);
  EXPECT_LT(worst, 2e-4);
}

// Relative error of G1 up to the last MERL cell (θ = 89.75°) and beyond: the estimation fits cells
// near the horizon at full weight, where G1 → 0 and an absolute error bound says little. Tabulating
// G1 instead of the projected area was 3.5 % low at 89.9° (GGX α = 0.2), and that moved the
// estimated D by 1 %.
TEST(ProjectedAreaMasking, RelativeErrorStaysSmallAtTheHorizon) {
  const double alpha = 0.2;
  const Ggx<double> ggx(&alpha);
  const Beckmann<double> beck(&alpha);
  const analysis::ProjectedAreaMasking mg([&](double c) { return ggx.D(c); }, {}, 181);
  const analysis::ProjectedAreaMasking mb([&](double c) { return beck.D(c); }, {}, 181);
  double worst = 0, worst_at = 0;
  for (double deg = 80; deg < 89.99; deg += 0.01) {
    const double c = std::cos(deg * kPi / 180);
    for (double rel : {mg.g1(c) / smith_g1(ggx, c) - 1, mb.g1(c) / smith_g1(beck, c) - 1})
      if (std::abs(rel) > worst) worst = std::abs(rel), worst_at = deg;
  }
  std::printf("max |G1 projected-area / closed form - 1| over 80..89.99 deg: %.2e at %.2f deg\n", worst, worst_at);
  EXPECT_LT(worst, 1e-3);
}

// From the table's own cells (exact values at the cell centres, ngan's weighting).
TEST(NdfEstimation, RecoversGgxFromTabulatedMaterial) {
  analysis::NdfEstimationOptions opt;
  opt.f0 = 0.05;
  const analysis::NdfEstimate e = analysis::estimate_tabulated_ndf(synthetic_ggx().samples(), opt);
  const analysis::TabulatedCookTorrance model = e.model();
  const double alpha = 0.2;
  const Ggx<double> ggx(&alpha);
  double worst = 0, worst_at = 0;
  for (double deg = 0; deg < 60; deg += 0.25) {
    const double c = std::cos(deg * kPi / 180);
    const double rel = std::abs(model.distribution().D(c) / ggx.D(c) - 1);
    if (rel > worst) worst = rel, worst_at = deg;
  }
  std::printf("GGX alpha=0.2 from a MERL table: %d masking iterations, max rel. error of D below 60 deg %.4f at %.2f "
              "deg; kd = %.4f %.4f %.4f, ks = %.4f %.4f %.4f\n",
              e.iterations, worst, worst_at, e.values.values[0][0], e.values.values[1][0], e.values.values[2][0],
              e.values.values[0][1], e.values.values[1][1], e.values.values[2][1]);
  for (double deg = 0; deg < 90; deg += 5)
    std::printf("  %4.0f deg: D/D_ggx - 1 = %+.4f\n", deg, model.distribution().D(std::cos(deg * kPi / 180)) / ggx.D(std::cos(deg * kPi / 180)) - 1);
  for (double r : e.residual_history) std::printf("  residual after iteration: %.6f\n", r);
  // Issue 6: < 2 %. Measured 0.91 % (4 Anderson-accelerated masking iterations, default tolerance);
  // iterated to 1e-7 it settles at 0.22 %, the D step's own error with the true G (the piecewise-
  // linear table). The former 2.25 % (3.0 % converged) came from the masking (projected_area_masking.h).
  EXPECT_LT(worst, 0.02);
  EXPECT_LE(e.iterations, 5);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(e.values.values[size_t(c)][0], kParams[c][0], 0.002);  // measured ≤ 1e-4
    EXPECT_NEAR(e.values.values[size_t(c)][1], kParams[c][1], 0.01 * kParams[c][1]);  // measured 0.3 %
  }
}

// Anisotropic GGX Cook-Torrance, αx = 0.2 along a tangent turned 0.5 rad, αy = 0.4, F0 = 0.3,
// ks = (1, 0.9, 0.7), seen from θi = 5°…85° × φi = 0°…330° (30° steps) towards rings
// 1 − cosθo = (k/16)² of 72 azimuths: 116 748 scattered samples, each weighted by its share of its
// ring's solid angle.
constexpr double kAx = 0.2, kAy = 0.4, kTangent = 0.5;

SampleSet anisotropic_ggx_samples(double kd_scale) {
  const Model& m = model_by_name("cook-torrance-ggx-aniso");
  ParamValues v = ParamValues::defaults(m.params());
  const double kd[3] = {0.1, 0.08, 0.05}, ks[3] = {1.0, 0.9, 0.7};
  for (int c = 0; c < 3; ++c) {
    v.set(m.params(), "kd", kd_scale * kd[c], c);
    v.set(m.params(), "ks", ks[c], c);
  }
  for (auto [name, x] : {std::pair{"alpha_x", kAx}, std::pair{"alpha_y", kAy}, std::pair{"phi_t", kTangent},
                         std::pair{"F0", 0.3}})
    v.set(m.params(), name, x);
  const Brdf brdf(m, v);
  SampleSet s;
  auto edge = [](int k) { return k <= 0 ? 0.0 : k >= 16 ? 1.0 : std::pow((k - 0.5) / 16, 2); };
  for (int i = 0; i < 9; ++i)
    for (int a = 0; a < 12; ++a)
      for (int k = 0; k < 16; ++k) {
        const int n = k == 0 ? 1 : 72;
        const double theta_o = std::acos(1 - std::pow(k / 16.0, 2));
        for (int j = 0; j < n; ++j) {
          const Vec3d wi = spherical_direction((5 + 10 * i) * kPi / 180, a * kPi / 6),
                      wo = spherical_direction(theta_o, 2 * kPi * j / n);
          s.push_back(wi, wo, brdf.eval(wi, wo), 2 * kPi * (edge(k + 1) - edge(k)) / n, true);
        }
      }
  return s;
}

// The largest |D_estimate / D_ggx − 1| for θh below each 5° band's upper edge (every 1° in θ and
// 5° in φ, between nodes too); [11] is the whole range below 60°.
std::array<double, 12> worst_below(const analysis::AnisotropicNdfEstimate& e) {
  const double widths[2] = {kAx, kAy};
  const GgxAnisotropic<double> ggx(widths);
  const TurnedFrame<double> lobe(kTangent);
  std::array<double, 12> worst{};
  for (int t = 0; t < 60; ++t)
    for (int p = 0; p < 72; ++p) {
      const Vec3d h = spherical_direction(t * kPi / 180, p * 5 * kPi / 180);
      const double rel = std::abs(e.D(h) / ggx.D(lobe.to_local(h)) - 1);
      for (int b = t / 5; b < 12; ++b) worst[size_t(b)] = std::max(worst[size_t(b)], rel);
    }
  return worst;
}

// The estimate from anisotropic_ggx_samples(kd_scale) with F0 given (or fitted), and its errors,
// printed.
struct Estimate {
  analysis::AnisotropicNdfEstimate e;
  std::array<double, 12> worst;
};
Estimate estimate(double kd_scale, const char* what, std::optional<double> f0 = 0.3) {
  analysis::NdfEstimationOptions opt;
  opt.f0 = f0;
  Estimate r{analysis::estimate_anisotropic_ndf(anisotropic_ggx_samples(kd_scale), opt), {}};
  r.worst = worst_below(r.e);
  const auto& v = r.e.values.values;
  std::printf("%s: %d masking iterations; max rel. error of D below 15/30/45/60 deg: %.4f %.4f %.4f %.4f; "
              "kd = %.4f %.4f %.4f, ks = %.4f %.4f %.4f, F0 = %.4f\n",
              what, r.e.iterations, r.worst[2], r.worst[5], r.worst[8], r.worst[11], v[0][0], v[1][0], v[2][0], v[0][1],
              v[1][1], v[2][1], r.e.f0);
  return r;
}

// Seed 002 §5.1 on anisotropic data: the hemisphere table, masked by its own projected area,
// reproduces the distribution to 2 % wherever θh < 60°.
TEST(AnisotropicNdfEstimation, RecoversAnisotropicGgx) {
  const Estimate r = estimate(0, "anisotropic GGX (0.2, 0.4) turned 0.5 rad, no diffuse");
  EXPECT_LT(r.worst[11], 0.02);
  EXPECT_LE(r.e.iterations, 5);
  for (int c = 0; c < 3; ++c) EXPECT_LT(r.e.values.values[size_t(c)][0], 1e-3);
  EXPECT_NEAR(r.e.values.values[2][1], 0.7, 0.01 * 0.7);
}

// F0 fitted in the outermost loop, with the hemisphere table (the isotropic estimate's F0 fits the
// azimuthal mean of D: from it the table's iteration went astray).
TEST(AnisotropicNdfEstimation, FittedF0IsTheLobes) {
  const Estimate r = estimate(0, "anisotropic GGX (0.2, 0.4) turned 0.5 rad, no diffuse, F0 fitted", std::nullopt);
  EXPECT_NEAR(r.e.f0, 0.3, 0.01);
  EXPECT_LT(r.worst[11], 0.02);
}

// With a diffuse term the far tail of D trades against kd (a flat D tail and the Lambertian term
// look alike, and the table's misfit near the peak moves kd): 2 % holds below 30°; the test
// prints the tail.
TEST(AnisotropicNdfEstimation, DiffuseLimitsTheTail) {
  const Estimate r = estimate(1, "anisotropic GGX (0.2, 0.4) turned 0.5 rad, kd (0.1, 0.08, 0.05)");
  EXPECT_LT(r.worst[5], 0.02);
  EXPECT_LT(r.worst[11], 0.1);
  EXPECT_NEAR(r.e.values.values[0][0], 0.1, 0.002);
}

}  // namespace
}  // namespace brdfkit

