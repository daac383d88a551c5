// Seed 000 Eq. 9 G1 approximation fitted to the numeric Smith G1 of SGD (DESIGN.md §4).
// Measure asserted: the paper's "L2 error", the SUM of squared residuals over the 1° table
// θj = j + ½ degrees (90 angles); shadowing/bagher_g1.h gives the evidence for this reading.
// The RMS and the 120-angle sum are printed too.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

#include "brdfkit/core/error.h"
#include "brdfkit/shadowing/bagher_g1.h"
#include "support/sgd_for_tests.h"
#include "support/test_util.h"

namespace brdfkit {
namespace {

std::vector<double> sgd_g1(double alpha, double p, const std::vector<double>& theta) {
  const double v[2] = {alpha, p};
  const test::TestSgd<double> sgd(v);
  std::vector<double> g(theta.size());
  for (size_t j = 0; j < theta.size(); ++j) g[j] = 1 / (1 + smith_lambda_integral(sgd, std::tan(theta[j])));
  return g;
}

TEST(BagherG1, Theta0MakesGrazingZero) {
  const BagherG1<double> g(2.6, 1.1e-7, 47.8);
  EXPECT_NEAR(g.eval(kPi / 2), 0.0, 1e-12);
  EXPECT_EQ(g.eval(g.theta0 - 0.01), 1.0);
}

TEST(BagherG1, FitsSgdOverTheParameterRange) {
  // Seed 000's materials: α 1e-4 … 0.4, p 0 … 1.7.
  const auto theta = bagher_g1_angles(90);
  double worst_ss = 0, worst_rms = 0;
  for (double alpha : {1e-4, 1e-3, 0.01, 0.03, 0.05, 0.1, 0.2, 0.4})
    for (double p : {0.0, 0.3, 0.6, 1.0, 1.4, 1.7}) {
      const auto g = sgd_g1(alpha, p, theta);
      const BagherG1Fit fit = fit_bagher_g1(theta, g);
      std::printf("alpha %-6g p %-4g  lambda %-10.4g c %-10.4g k %-8.4g theta0 %-8.4f  sum_sq %.3g  rms %.3g\n",
                  alpha, p, fit.lambda, fit.c, fit.k, fit.theta0, fit.sum_sq, fit.rms);
      EXPECT_LT(fit.sum_sq, 1e-5) << "alpha " << alpha << " p " << p;
      worst_ss = std::max(worst_ss, fit.sum_sq);
      worst_rms = std::max(worst_rms, fit.rms);
      // The reported (λ, c, k, θ0) reproduce the fitted curve, where c is representable: for the
      // sharpest G1 (α ≤ 1e-3) c = log(1 + 1/λ)/(π/2 − θ0)^k leaves the double range.
      if (!(std::isfinite(fit.c) && fit.c > 0)) continue;
      const auto m = fit.model();
      double ss = 0;
      for (size_t j = 0; j < theta.size(); ++j) ss += std::pow(m.eval(theta[j]) - g[j], 2);
      EXPECT_NEAR(ss, fit.sum_sq, 1e-9 + 1e-3 * fit.sum_sq);
    }
  std::printf("worst over the grid: sum of squares %.3g, RMS %.3g (1-degree table, 90 angles)\n", worst_ss, worst_rms);
}

// Over 120 angles the sum is 4/3 larger and Eq. 9's three parameters cannot get below 1e-5 at
// α = 0.05, p = 1.7: the global minimum there is 1.165e-5 (bagher_g1.h). The fit must find it.
TEST(BagherG1, Eq9FloorOn120Angles) {
  const auto theta = bagher_g1_angles(120);
  const BagherG1Fit fit = fit_bagher_g1(theta, sgd_g1(0.05, 1.7, theta));
  std::printf("alpha 0.05, p 1.7, 120 angles: sum of squares %.4g (Eq. 9's global minimum 1.165e-5)\n", fit.sum_sq);
  EXPECT_LT(fit.sum_sq, 1.17e-5);
}

TEST(BagherG1, DesignReferenceCase) {
  // DESIGN.md §4: an independent fit at α = 0.05, p = 0.6, 120 angles reached RMS 1.5e-4
  // (sum of squares 2.7e-6); ours must be at least as good.
  const auto theta = bagher_g1_angles(120);
  const BagherG1Fit fit = fit_bagher_g1(theta, sgd_g1(0.05, 0.6, theta));
  std::printf("alpha 0.05, p 0.6: sum of squares %.3g, RMS %.3g\n", fit.sum_sq, fit.rms);
  EXPECT_LT(fit.sum_sq, 2.8e-6);
}

TEST(BagherG1, PublishedFits) {
  BRDFKIT_REQUIRE_DATA("published-fits/bagher2012-sgd.json");
  std::ifstream in(test::data_dir() / "published-fits/bagher2012-sgd.json");
  const auto j = nlohmann::json::parse(in);
  const auto theta = bagher_g1_angles(90);
  for (const char* name : {"alum-bronze", "blue-fabric", "gold-metallic-paint", "white-paint", "black-obsidian"}) {
    ASSERT_TRUE(j["materials"].contains(name)) << name;
    const auto& lobe = j["materials"][name][1]["params"];
    for (int c = 0; c < 3; ++c) {
      const double alpha = lobe["alpha"][c], p = lobe["p"][c];
      const BagherG1<double> pub(lobe["Lambda"][c].get<double>(), lobe["c"][c].get<double>(), lobe["k"][c].get<double>(),
                                 lobe["theta0"][c].get<double>());
      const double theta0_formula = BagherG1<double>::theta0_of(pub.lambda, pub.c, pub.k);
      const auto g = sgd_g1(alpha, p, theta);
      double ss_pub = 0;
      for (size_t i = 0; i < theta.size(); ++i) ss_pub += std::pow(pub.eval(theta[i]) - g[i], 2);
      const BagherG1Fit fit = fit_bagher_g1(theta, g);
      std::printf("%-20s %c alpha %-9.4g p %-7.4g published: sum_sq %.3g (theta0 %.5f, formula %.5f)  refit: sum_sq %.3g rms %.3g\n",
                  name, "RGB"[c], alpha, p, ss_pub, pub.theta0, theta0_formula, fit.sum_sq, fit.rms);
      EXPECT_LT(fit.sum_sq, 1e-5) << name << " " << c;
      // The refit is never worse than the published parameters on this measure (up to the solver's
      // tolerance); several published fits miss 1e-5 on it (see the printed sums).
      EXPECT_LE(fit.sum_sq, ss_pub * 1.01 + 1e-9) << name << " " << c;
    }
  }
}

TEST(BagherG1, BadInput) {
  std::vector<double> t{0.1, 0.2}, g{1.0};
  EXPECT_THROW(fit_bagher_g1(t, g), InputError);
  EXPECT_THROW(fit_bagher_g1(std::vector<double>{}, std::vector<double>{}), InputError);
  std::vector<double> gn{1.0, std::nan("")};
  EXPECT_THROW(fit_bagher_g1(t, gn), InputError);
}

}  // namespace
}  // namespace brdfkit
