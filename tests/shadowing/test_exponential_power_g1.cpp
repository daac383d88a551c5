// Seed 004 §5.5 tabulated G1 of the exponential power distribution against the direct integral.
#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <random>

#include "brdfkit/shadowing/exponential_power_g1.h"

namespace brdfkit {
namespace {

// σ ≠ 1 directly from seed 004 Eq. 19 (DESIGN.md §3), to check that G1 depends on σ tanθ only.
struct ExpPower {
  double sigma, p;
  double P22(double x) const {
    return p / (kPi * sigma * sigma * boost::math::tgamma(1 / p)) * std::exp(-std::pow(x / (sigma * sigma), p));
  }
};

TEST(ExponentialPowerG1, DependsOnSigmaTanThetaOnly) {
  for (double p : {0.3, 0.8, 2.0}) {
    const double z = 0.9;
    const double ref = ExponentialPowerG1Table::g1_direct(z, p);
    for (double sigma : {0.05, 0.4, 1.7}) {
      const double g = 1 / (1 + smith_lambda_integral(ExpPower{sigma, p}, z / sigma));
      EXPECT_NEAR(g, ref, 1e-10) << p << " " << sigma;
    }
  }
}

TEST(ExponentialPowerG1, NormalizationOfUnitDistribution) {
  // ∫₀^∞ P22 dx = 1/π (DESIGN.md §3), by Boost's exp-sinh quadrature.
  boost::math::quadrature::exp_sinh<double> integrator;
  for (double p : {0.2, 1.0, 4.0}) {
    const ExponentialPowerG1Table::UnitDistribution<double> d(p);
    const double s = integrator.integrate([&](double x) { return d.P22(x); }, 0.0, std::numeric_limits<double>::infinity());
    EXPECT_NEAR(s * kPi, 1.0, 1e-9) << p;
  }
}

TEST(ExponentialPowerG1, TableMatchesDirectIntegral) {
  const auto& table = ExponentialPowerG1Table::instance();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0, worst_fitted = 0, worst_z = 0, worst_p = 0;
  for (int i = 0; i < 3000; ++i) {
    const double p = 0.1 * std::pow(50.0, u(rng));
    const double z = 1e-3 * std::pow(1e6, u(rng));
    const double e = std::abs(table.g1(z, p) - ExponentialPowerG1Table::g1_direct(z, p));
    if (e > worst) {
      worst = e;
      worst_z = z;
      worst_p = p;
    }
    if (p >= 0.3 && p <= 0.95) worst_fitted = std::max(worst_fitted, e);
  }
  std::printf("exponential power G1 table (%d x %d, bilinear) vs direct: max |dG1| %.3g (at z %.3g, p %.3g); "
              "p in [0.3, 0.95]: %.3g\n",
              ExponentialPowerG1Table::kNa, ExponentialPowerG1Table::kNb, worst, worst_z, worst_p, worst_fitted);
  EXPECT_LT(worst, 2e-3);
  EXPECT_EQ(table.g1(0.0, 0.5), 1.0);
  EXPECT_NEAR(table.g1(1e12, 0.5), 0.0, 1e-4);
}

TEST(ExponentialPowerG1, Jets) {
  using J = ceres::Jet<double, 2>;
  const auto& table = ExponentialPowerG1Table::instance();
  const J g = table.g1(J(0.8, 0), J(0.6, 1));
  EXPECT_DOUBLE_EQ(g.a, table.g1(0.8, 0.6));
  const double h = 1e-3;
  const double dz = (ExponentialPowerG1Table::g1_direct(0.8 + h, 0.6) - ExponentialPowerG1Table::g1_direct(0.8 - h, 0.6)) / (2 * h);
  EXPECT_NEAR(g.v[0], dz, 0.05 * std::abs(dz));
}

}  // namespace
}  // namespace brdfkit
