// The cylinder profile of `poulin-fournier` (models/cylinder_profile.h): the parts lit from any
// angle project onto P cos a, whatever the shadows; and the model at the published parameters
// of seed 002 (Fig. 9) is finite everywhere and keeps its highlight across the cylinders.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "brdfkit/models/cylinder_profile.h"
#include "brdfkit/models/model.h"

namespace brdfkit {
namespace {

// A heightfield's lit part seen from the light covers the light's view of one period exactly:
// arc + gap projections = P cos a. A wrong shadow bound leaves a hole or an overlap.
TEST(CylinderProfile, LitPartsProjectOntoThePeriod) {
  double worst = 0;
  int shadowed = 0;
  for (double h : {0.05, 0.3, 0.5, 0.8, 1.0})
    for (double d : {0.0, 0.1, 0.5, 2.0})
      for (int k = -89; k <= 89; ++k) {
        const double a = k * kPi / 180;
        const CylinderProfile<double> p(h, d);
        const auto lit = p.lit(a);
        const double covered = p.arc_projection(a, lit.arc) + p.gap_projection(a, lit.gap);
        worst = std::max(worst, std::abs(covered - p.period * std::cos(a)) / p.period);
        // Shadows count when part of the arc facing the light is dark.
        if (!lit.arc.empty() && lit.arc.hi < std::min(p.theta_m, a + kPi / 2) - 1e-9 && a > 0) ++shadowed;
      }
  EXPECT_LT(worst, 1e-14);
  EXPECT_GT(shadowed, 300);
  std::printf("lit arc + gap projections vs P cos a over 20 profiles x 179 angles: worst %.1e (%d shadowed cases)\n",
              worst, shadowed);
}

// Mirror symmetry: the lit parts from −a are those from a reflected (θ → −θ, y → P − y).
TEST(CylinderProfile, MirrorImageOfTheOtherSide) {
  const CylinderProfile<double> p(0.6, 0.25);
  for (double a : {0.1, 0.7, 1.2, 1.5}) {
    const auto l = p.lit(a), r = p.lit(-a);
    EXPECT_NEAR(r.arc.lo, -l.arc.hi, 1e-15);
    EXPECT_NEAR(r.arc.hi, -l.arc.lo, 1e-15);
    EXPECT_NEAR(r.gap.lo, p.period - l.gap.hi, 1e-15);
  }
}

// Seed 002 Fig. 9's brushed aluminium (n = 3000, d = 0.18, h = 0.5): finite and non-negative at
// every pair of a 10° grid (grazing included), its highlight spread across the cylinders (a
// mirror pair tilted 40° across them stays bright) and sharp along them (10° along: dark).
TEST(PoulinFournier, PublishedBrushedAluminiumEvaluates) {
  const Model& m = model_by_name("poulin-fournier");
  ParamValues v = ParamValues::defaults(m.params());
  for (auto [name, x] : {std::pair{"kd", 0.05}, std::pair{"ks", 0.8}, std::pair{"n", 3000.0}, std::pair{"d", 0.18},
                         std::pair{"h", 0.5}, std::pair{"phi_t", 0.0}})
    v.set(m.params(), name, x);
  int pairs = 0;
  for (int ti = 0; ti <= 9; ++ti)
    for (int pi = 0; pi < 36; ++pi)
      for (int to = 0; to <= 9; ++to)
        for (int po = 0; po < 36; po += 5) {
          const Vec3d wi = spherical_direction(std::min(ti * 10.0, 89.9) * kPi / 180, pi * 10 * kPi / 180);
          const Vec3d wo = spherical_direction(std::min(to * 10.0, 89.9) * kPi / 180, po * 10 * kPi / 180);
          const double f = m.eval(v.channel(0), 0, wi, wo);
          ASSERT_TRUE(std::isfinite(f) && f >= 0) << f << " at " << wi.transpose() << " / " << wo.transpose();
          ++pairs;
        }
  EXPECT_EQ(pairs, 28800);
  // The axis is x: tilting across it is the y-z plane, along it the x-z plane.
  const double peak = m.eval(v.channel(0), 0, spherical_direction(0.3, kPi / 2), spherical_direction(0.3, -kPi / 2));
  const double across =
      m.eval(v.channel(0), 0, spherical_direction(0.3, kPi / 2), spherical_direction(0.3 + 0.7, -kPi / 2));
  const double along = m.eval(v.channel(0), 0, spherical_direction(0.3, 0.0), spherical_direction(0.3 + 0.17, kPi));
  EXPECT_GT(across, 0.1 * peak);
  EXPECT_LT(along, 0.02 * peak);
}

}  // namespace
}  // namespace brdfkit
