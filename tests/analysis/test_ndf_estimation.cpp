// Tabulated-NDF estimation (seed 002 §5.1) on a synthetic MERL-format material with known D.
#include <gtest/gtest.h>

#include <cmath>

#include "brdfkit/analysis/ndf_estimation.h"
#include "brdfkit/analysis/projected_area_masking.h"
#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/measured/merl_brdf.h"
#include "brdfkit/measured/merl_tabulate.h"
#include "brdfkit/models/model.h"
#include "brdfkit/ndf/beckmann.h"
#include "brdfkit/ndf/ggx.h"
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

}  // namespace
}  // namespace brdfkit

