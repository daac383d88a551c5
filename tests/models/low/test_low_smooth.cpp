// Löw et al. 2012 smooth-surface models against values computed here from the paper's own
// equations in angles (seed 003 Eq. 9–14, 34), with the Fresnel reflectance from Snell's law
// and the s/p amplitudes (independent of the Cook-Torrance form the model uses).
#include <gtest/gtest.h>

#include <random>

#include "brdfkit/models/low_smooth.h"
#include "brdfkit/models/model.h"

namespace brdfkit {
namespace {

// Unpolarized dielectric reflectance from Snell + Fresnel amplitudes (Born & Wolf).
double fresnel_snell(double cos_i, double eta) {
  const double sin_t = std::sqrt(1 - cos_i * cos_i) / eta;
  const double cos_t = std::sqrt(1 - sin_t * sin_t);
  const double rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  const double rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return 0.5 * (rs * rs + rp * rp);
}

struct Angles {
  double ti, pi, to, po;
};

// Seed 003 Eq. 12 / Eq. 34 in angles: Lp = sinθi (cosφi, sinφi), Vp likewise, Dp = Lp + Vp,
// θd′ = arcsin(‖Lp − Vp‖/2) (Eq. 13).
double paper_value(const Angles& a, double kd, double a1, double b1, double c1, double a2, double b2, double c2,
                   double eta, bool two_lobes) {
  const double lx = std::sin(a.ti) * std::cos(a.pi), ly = std::sin(a.ti) * std::sin(a.pi);
  const double vx = std::sin(a.to) * std::cos(a.po), vy = std::sin(a.to) * std::sin(a.po);
  const double dp = std::hypot(lx + vx, ly + vy);
  const double theta_d = std::asin(std::hypot(lx - vx, ly - vy) / 2);
  const double f = fresnel_snell(std::cos(theta_d), eta);
  auto s = [dp](double a_, double b_, double c_) { return a_ / std::pow(1 + b_ * dp * dp, c_); };
  if (!two_lobes) return kd / kPi + f * s(a1, b1, c1);
  return kd / kPi + s(a1, b1, c1) + f * s(a2, b2, c2);
}

TEST(LowSmooth, MatchesPaperEquationsInAngles) {
  const Model& m = model_by_name("low-smooth");
  std::mt19937_64 rng(2012);
  std::uniform_real_distribution<double> u(0, 1);
  const double sets[][5] = {{0.1, 164.2, 16711.8, 0.6635, 1.5608},  // alum-bronze's published E2 fit (R)
                            {0.3, 2.0, 40.0, 1.0, 1.3},
                            {0.0, 10.0, 1000.0, 2.2, 9.0}};
  double worst = 0;
  for (const auto& s : sets) {
    ParamValues v = ParamValues::defaults(m.params());
    for (int i = 0; i < 5; ++i) v.set(m.params(), m.params()[size_t(i)].name, s[i]);
    for (int k = 0; k < 300; ++k) {
      const Angles a{std::acos(u(rng)), 2 * kPi * u(rng), std::acos(u(rng)), 2 * kPi * u(rng)};
      const double want = paper_value(a, s[0], s[1], s[2], s[3], 0, 0, 0, s[4], false);
      const double got = m.eval(v.channel(0), 0, spherical_direction(a.ti, a.pi), spherical_direction(a.to, a.po));
      worst = std::max(worst, std::abs(got - want) / want);
    }
  }
  EXPECT_LT(worst, 1e-10);
}

TEST(LowSmooth, NormalIncidenceIsKdOverPiPlusAF0) {
  const Model& m = model_by_name("low-smooth");
  ParamValues v = ParamValues::defaults(m.params());
  v.set(m.params(), "kd", 0.2);
  v.set(m.params(), "A", 3.0);
  v.set(m.params(), "B", 500.0);
  v.set(m.params(), "C", 0.8);
  v.set(m.params(), "eta", 1.5);
  const Vec3d n = Vec3d::UnitZ();
  // F(0; 1.5) = ((η − 1)/(η + 1))² = 0.04.
  EXPECT_NEAR(m.eval(v.channel(0), 0, n, n), 0.2 / kPi + 3.0 * 0.04, 1e-15);
  // At the mirror direction Dp = 0 and θd′ = θo: ρ − kd/π = A F(θo).
  const Vec3d wo = spherical_direction(1.0, 0.4), wi = spherical_direction(1.0, 0.4 + kPi);
  EXPECT_NEAR(m.eval(v.channel(0), 0, wi, wo), 0.2 / kPi + 3.0 * fresnel_snell(std::cos(1.0), 1.5), 1e-13);
}

TEST(LowSmooth2, MatchesPaperEq34) {
  const Model& m = model_by_name("low-smooth-2");
  std::mt19937_64 rng(34);
  std::uniform_real_distribution<double> u(0, 1);
  ParamValues v = ParamValues::defaults(m.params());
  const std::pair<const char*, double> set[] = {{"kd", 0.15}, {"A1", 0.4}, {"B1", 12.0}, {"C1", 0.7},
                                                {"A2", 30.0}, {"B2", 3000.0}, {"C2", 1.3}, {"eta", 1.7}};
  for (const auto& [name, value] : set) v.set(m.params(), name, value);
  double worst = 0;
  for (int k = 0; k < 500; ++k) {
    const Angles a{std::acos(u(rng)), 2 * kPi * u(rng), std::acos(u(rng)), 2 * kPi * u(rng)};
    const double want = paper_value(a, 0.15, 0.4, 12.0, 0.7, 30.0, 3000.0, 1.3, 1.7, true);
    const double got = m.eval(v.channel(0), 0, spherical_direction(a.ti, a.pi), spherical_direction(a.to, a.po));
    worst = std::max(worst, std::abs(got - want) / want);
  }
  EXPECT_LT(worst, 1e-10);
}

}  // namespace
}  // namespace brdfkit
