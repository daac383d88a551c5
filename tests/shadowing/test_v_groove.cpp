// Cook-Torrance V-groove G (DESIGN.md §4).
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <random>

#include "brdfkit/core/vec.h"
#include "brdfkit/shadowing/v_groove.h"

namespace brdfkit {
namespace {

TEST(VGroove, ValuesAndReciprocity) {
  // Normal incidence and mirror view: h = n, G = min(1, 2, 2) = 1.
  EXPECT_DOUBLE_EQ(v_groove_g(Vec3d(0, 0, 1), Vec3d(0, 0, 1)), 1.0);
  // In-plane, θi = 80°, θo = 80° on the same side (back-scatter): h = wi = wo,
  // G = min(1, 2 cos80° cos80° / cos0°) = 2 cos²80°.
  const double t = 80 * kPi / 180;
  const Vec3d w(std::sin(t), 0, std::cos(t));
  EXPECT_NEAR(v_groove_g(w, w), 2 * std::cos(t) * std::cos(t), 1e-15);
  // Hand-computed case: wi at 60°, wo at 0°: h at 30°, wo·h = cos30°,
  // G = min(1, 2 cos30° cos0° / cos30°, 2 cos30° cos60° / cos30°) = min(1, 2, 1) = 1;
  // wi at 85°: h at 42.5°, G = 2 cos42.5° cos85° / cos42.5° = 2 cos85°.
  const double a = 85 * kPi / 180;
  EXPECT_NEAR(v_groove_g(Vec3d(std::sin(a), 0, std::cos(a)), Vec3d(0, 0, 1)), 2 * std::cos(a), 1e-15);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 1000; ++i) {
    const Vec3d wi = spherical_direction(0.5 * kPi * u(rng), 2 * kPi * u(rng));
    const Vec3d wo = spherical_direction(0.5 * kPi * u(rng), 2 * kPi * u(rng));
    const double g = v_groove_g(wi, wo);
    EXPECT_GE(g, 0.0);
    EXPECT_LE(g, 1.0);
    EXPECT_DOUBLE_EQ(g, v_groove_g(wo, wi));
  }
  EXPECT_EQ(v_groove_g(Vec3d(0, 0, -1), Vec3d(0, 0, 1)), 0.0);
}

TEST(VGroove, Jets) {
  using J = ceres::Jet<double, 1>;
  const double a = 85 * kPi / 180;
  const Vec3<J> wi(J(std::sin(a)), J(0), J(std::cos(a), 0));
  const J g = v_groove_g(wi, Vec3<J>(J(0), J(0), J(1)));
  EXPECT_NEAR(g.a, 2 * std::cos(a), 1e-15);
}

}  // namespace
}  // namespace brdfkit
