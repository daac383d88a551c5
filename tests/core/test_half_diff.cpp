#include <gtest/gtest.h>

#include <random>

#include "brdfkit/core/half_diff.h"

using namespace brdfkit;

TEST(HalfDiff, RoundTripRandomPairs) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 1000; ++k) {
    const Vec3d wi = spherical_direction(std::acos(u(rng)), 2 * kPi * u(rng));
    const Vec3d wo = spherical_direction(std::acos(u(rng)), 2 * kPi * u(rng));
    Vec3d wi2, wo2;
    from_half_diff(to_half_diff(wi, wo), wi2, wo2);
    EXPECT_NEAR((wi - wi2).norm(), 0, 1e-12);
    EXPECT_NEAR((wo - wo2).norm(), 0, 1e-12);
  }
}

TEST(HalfDiff, KnownConfigurations) {
  // Normal incidence and mirror reflection: h = n, θd = θi.
  const double t = 0.4;
  HalfDiff hd = to_half_diff(spherical_direction(t, 0.0), spherical_direction(t, kPi));
  EXPECT_NEAR(hd.theta_h, 0, 1e-12);
  EXPECT_NEAR(hd.theta_d, t, 1e-12);
  // wi = wo: θd = 0, θh = θi.
  hd = to_half_diff(spherical_direction(t, 1.0), spherical_direction(t, 1.0));
  EXPECT_NEAR(hd.theta_h, t, 1e-12);
  EXPECT_NEAR(hd.theta_d, 0, 1e-7);
  // In-plane configuration: wi at 60°, wo at 20° on the opposite side; h tilts 20° towards wi,
  // wi is 40° from h in the incidence plane, so φd = 0 with MERL's rotations.
  hd = to_half_diff(spherical_direction(60 * kPi / 180, 0.0), spherical_direction(20 * kPi / 180, kPi));
  EXPECT_NEAR(hd.theta_h, 20 * kPi / 180, 1e-12);
  EXPECT_NEAR(hd.theta_d, 40 * kPi / 180, 1e-12);
  EXPECT_NEAR(hd.phi_d, 0, 1e-12);
}
