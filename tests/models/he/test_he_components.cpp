// He et al. 1991's shadowing (Eq. 24–25) and effective roughness (Eq. 80–83).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <random>
#include <vector>

#include "brdfkit/models/he_batch_block.h"
#include "brdfkit/models/he_effective_roughness.h"
#include "brdfkit/models/he_shadowing.h"
#include "brdfkit/ndf/beckmann.h"

namespace brdfkit {
namespace {

// With the errata's e^{−a²}, Eq. 25's Λ is Smith's Λ of a Beckmann surface with α = 2σ0/τ, so
// S(θ) = (1 − ½ erfc(a)) · G1_Beckmann(θ). The Λ printed in the paper (no e^{−a²}) is not: the
// test measures how far it is off (reported as a paper error).
TEST(HeShadowing, ErrataLambdaIsSmithBeckmann) {
  double worst_printed = 0, worst_angle = 0;
  for (double sigma0 : {0.05, 0.18, 1.0}) {
    for (double tau : {0.5, 3.0, 20.0}) {
      const double alpha = 2 * sigma0 / tau;
      const Beckmann<double> beckmann(&alpha);
      for (double deg = 1; deg < 89.5; deg += 2) {
        const double t = deg * kPi / 180;
        const double a = tau / (2 * sigma0 * std::tan(t));
        const double g1 = 1 / (1 + beckmann.Lambda(std::tan(t)));
        const double s = he_shadowing(std::cos(t), sigma0, tau);
        EXPECT_NEAR(s, (1 - 0.5 * std::erfc(a)) * g1, 1e-12) << sigma0 << " " << tau << " " << deg;
        const double printed_lambda = 0.5 * (1 / (std::sqrt(kPi) * a) - std::erfc(a));
        const double printed = (1 - 0.5 * std::erfc(a)) / (printed_lambda + 1);
        if (std::fabs(printed / s - 1) > worst_printed) worst_printed = std::fabs(printed / s - 1), worst_angle = deg;
      }
    }
  }
  std::printf("[ he shadow ] Eq. 25 as printed (no exp(-a^2)) is off by up to %.1f%% (at %.0f deg)\n",
              100 * worst_printed, worst_angle);
  EXPECT_GT(worst_printed, 0.1);
  // Limits: 1 at normal incidence, 0 at grazing.
  EXPECT_EQ(he_shadowing(1.0, 0.18, 3.0), 1.0);
  EXPECT_EQ(he_shadowing(0.0, 0.18, 3.0), 0.0);
}

// z0 solves Eq. 81, σ ≤ σ0, σ = σ0 at normal incidence, symmetric in θi and θr.
TEST(HeEffectiveRoughness, SolvesEq81) {
  for (double sigma0 : {0.01, 0.18, 2.0}) {
    for (double tau : {0.1, 3.0, 50.0}) {
      EXPECT_EQ(he_effective_roughness(1.0, 1.0, sigma0, tau), sigma0);
      for (double di : {0.0, 30.0, 70.0, 89.0}) {
        for (double dr : {10.0, 60.0, 85.0}) {
          const double ci = std::cos(di * kPi / 180), cr = std::cos(dr * kPi / 180);
          const double s = he_effective_roughness(ci, cr, sigma0, tau);
          ASSERT_TRUE(s > 0 && s <= sigma0) << s;
          EXPECT_EQ(s, he_effective_roughness(cr, ci, sigma0, tau));
          const double z0 = sigma0 * std::sqrt(sigma0 * sigma0 / (s * s) - 1);  // Eq. 80 inverted
          auto kf = [&](double t) { return std::tan(t) * std::erfc(tau / (2 * sigma0 * std::tan(t))); };
          const double rhs = sigma0 / 4 * (kf(di * kPi / 180) + kf(dr * kPi / 180)) *
                             std::exp(-z0 * z0 / (2 * sigma0 * sigma0));
          EXPECT_NEAR(std::sqrt(kPi / 2) * z0, rhs, 1e-9 * sigma0 * (1 + rhs / sigma0)) << di << " " << dr;
        }
      }
    }
  }
}

// The z0 equation x e^{x²/2} = f0 (Eq. 81 over σ0), solved as x = sqrt(W0(f0²)): residual at
// round-off from nearly smooth surfaces (f0 = 1e-14) to grazing directions (f0 = 1e6).
TEST(HeEffectiveRoughness, LambertWSolvesEq81) {
  double worst = 0;
  for (double f = 1e-14; f < 1e6; f *= 1.07) {
    const double x = he_detail::solve_z0_ratio(f);
    worst = std::max(worst, std::abs(x * std::exp(0.5 * x * x) - f) / f);
  }
  std::printf("[ he z0 ] worst relative residual of x e^(x^2/2) = f0, f0 in [1e-14, 1e6]: %.3g\n", worst);
  EXPECT_LE(worst, 1e-14);
  EXPECT_EQ(he_detail::solve_z0_ratio(0.0), 0.0);
}

// The vector lanes' x = sqrt(W0(f0²)) (Winitzki's start, two Halley steps) against Boost's
// lambert_w0 up to f0 = 1e150, where f0² nears the largest double, and x = f0 below 1e-150.
TEST(HeEffectiveRoughness, VectorLanesAreBoostsLambertW) {
  std::vector<double> f{0.0, 1e-320, 1e-100, 1.0000001e-100, 1e-30};
  for (double v = 1e-14; v < 1e150; v *= 1.013) f.push_back(v);
  while (f.size() % kHePairLanes) f.push_back(1.0);
  double worst = 0;
  for (std::size_t b = 0; b < f.size(); b += kHePairLanes) {
    double x[kHePairLanes];
    he_z0_ratio_lanes(f.data() + b, x);
    for (std::size_t l = 0; l < kHePairLanes; ++l) {
      // Where f0² underflows (Boost then gives 0), x = f0 (1 − f0²/2 + …) is f0.
      if (f[b + l] < 1e-150) {
        ASSERT_EQ(x[l], f[b + l]);
        continue;
      }
      worst = std::max(worst, std::abs(x[l] / he_detail::solve_z0_ratio(f[b + l]) - 1));
    }
  }
  std::printf("[ he z0 ] vector lanes vs Boost's lambert_w0, f0 in [1e-320, 1e150]: worst relative %.3g\n", worst);
  EXPECT_LE(worst, 1e-15);
}

// S(θi)S(θr) and σ of the vector lanes against HeSlopeTerms and he_effective_roughness_of: from
// normal incidence to cosines of 1e-100, smooth to rough surfaces.
TEST(HeEffectiveRoughness, VectorPairLanesAreTheScalarTerms) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0;
  for (const auto& [sigma0, tau] : {std::pair{0.005, 50.0}, std::pair{0.18, 3.0}, std::pair{1.5, 0.5}, std::pair{2.0, 8.0}}) {
    for (int b = 0; b < 200; ++b) {
      double ci[kHePairLanes], co[kHePairLanes], shadow[kHePairLanes], sigma[kHePairLanes];
      for (std::size_t l = 0; l < kHePairLanes; ++l) {
        ci[l] = u(rng);
        co[l] = std::pow(10.0, -100 * u(rng) * u(rng) * u(rng));  // down to grazing
      }
      if (b == 0) ci[0] = co[1] = 1.0, ci[2] = co[2] = kHePairMinCos, ci[3] = co[3] = 1 - 1e-13;
      he_pair_shape_lanes(sigma0, tau, ci, co, shadow, sigma);
      for (std::size_t l = 0; l < kHePairLanes; ++l) {
        const HeSlopeTerms<double> si(ci[l], sigma0, tau), so(co[l], sigma0, tau);
        const double want_shadow = si.shadowing * so.shadowing;
        const double want_sigma = he_effective_roughness_of(si.k_factor + so.k_factor, sigma0);
        ASSERT_GT(want_sigma, 0) << ci[l] << " " << co[l];
        worst = std::max(worst, std::abs(sigma[l] / want_sigma - 1));
        if (want_shadow > 1e-300) worst = std::max(worst, std::abs(shadow[l] / want_shadow - 1));
        else ASSERT_LE(shadow[l], 1e-300) << ci[l] << " " << co[l];
      }
    }
  }
  std::printf("[ he pair ] vector lanes vs scalar shadowing and sigma: worst relative %.3g\n", worst);
  EXPECT_LE(worst, 1e-14);
}

}  // namespace
}  // namespace brdfkit
