// `poulin-fournier` against its definition computed by brute force: the cylinders of radius 1,
// raised h, d apart, their axis at phi_t, sampled at 2·10⁵ points of one period's arc and gap;
// each point's normal in 3-D, its Phong lobe (n + 2)/(2π) max(0, R·wo)ⁿ with R = wi mirrored in
// 3-D, and whether it is lit and seen by casting 2-D rays at the five nearest cylinders:
//   ρ = kd/π + ks/(P cosθi cosθo) Σ f_e (N·wi)(N·wo) V(wi) V(wo) Δℓ.
// None of the model's interval bounds, peak quadrature or cross-section algebra is used. The sum is
// a midpoint rule with lit/seen edges inside cells: bound 2·10⁻⁴ relative.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "brdfkit/models/model.h"
#include "reference_pairs.h"

namespace brdfkit::test::ref {
namespace {


struct Surface {
  double n, d, h, phi;
};

// Does the 2-D ray from q along v (v_z > 0) meet a cylinder of radius 1 centred at (k P, h − 1),
// k ≠ skip, |k| ≤ 2?
bool blocked(double qy, double qz, double vy, double vz, const Surface& s, double period, int skip) {
  for (int k = -2; k <= 2; ++k) {
    if (k == skip) continue;
    const double cy = qy - k * period, cz = qz - (s.h - 1);  // q − centre
    const double a = vy * vy + vz * vz, b = cy * vy + cz * vz, c = cy * cy + cz * cz - 1;
    const double disc = b * b - a * c;
    if (disc > 0 && (-b + std::sqrt(disc)) / a > 1e-12) return true;
  }
  return false;
}

double brute_force_lobe(const Surface& s, const Vec3d& wi, const Vec3d& wo, int points = 200000) {
  // The axis is (cos φ, sin φ, 0); b runs across the cylinders.
  const Vec3d b(-std::sin(s.phi), std::cos(s.phi), 0), z(0, 0, 1);
  const double theta_m = std::acos(1 - s.h), half = std::sin(theta_m), period = 2 * half + s.d;
  auto element = [&](const Vec3d& normal, double qy, double qz, int skip) {
    const double ni = normal.dot(wi), no = normal.dot(wo);
    if (!(ni > 0 && no > 0)) return 0.0;
    if (blocked(qy, qz, wi.dot(b), wi.z(), s, period, skip) || blocked(qy, qz, wo.dot(b), wo.z(), s, period, skip))
      return 0.0;
    const Vec3d r = 2 * ni * normal - wi;
    return (s.n + 2) / (2 * kPi) * std::pow(std::max(0.0, r.dot(wo)), s.n) * ni * no;
  };
  double sum = 0;
  const double dtheta = 2 * theta_m / points;
  for (int k = 0; k < points; ++k) {
    const double th = -theta_m + (k + 0.5) * dtheta;
    sum += element(std::sin(th) * b + std::cos(th) * z, std::sin(th), s.h - 1 + std::cos(th), 0) * dtheta;
  }
  const double dy = s.d / points;
  for (int k = 0; k < points && s.d > 0; ++k) sum += element(z, half + (k + 0.5) * dy, 0.0, 99) * dy;
  return sum / (period * wi.z() * wo.z());
}

// kd/π + ks·lobe, the lobe cached per direction pair (the channels share it).
Reference reference(const Model& m, const ParamValues& v, const Surface& s, double scale = 1) {
  auto cache = std::make_shared<std::map<std::array<double, 6>, double>>();
  return [&m, v, s, scale, cache](int c, const Vec3d& wi, const Vec3d& wo) {
    const std::array<double, 6> key{wi.x(), wi.y(), wi.z(), wo.x(), wo.y(), wo.z()};
    auto it = cache->find(key);
    if (it == cache->end()) it = cache->emplace(key, brute_force_lobe(s, wi, wo)).first;
    return param(m, v, "kd", c) / kPi + scale * param(m, v, "ks", c) * it->second;
  };
}

TEST(PoulinFournierReference, CylindersByRayCasting) {
  const Model& m = model_by_name("poulin-fournier");
  // Half cylinders close together (deep shadows, the tangent case), shallow caps far apart (the
  // corner case), a mid profile turned, and Ngan et al.'s brushed aluminium (seed 002 Fig. 9).
  for (const Surface& s : {Surface{30, 0.5, 0.5, 0.0}, Surface{200, 0.1, 1.0, 0.7}, Surface{5, 2.0, 0.2, -1.2},
                           Surface{60, 0.0, 0.8, 2.5}, Surface{3000, 0.18, 0.5, 0.3}}) {
    const ParamValues v = values_of(m, {{"kd", 0.1, 0},
                                        {"kd", 0.05, 1},
                                        {"kd", 0.2, 2},
                                        {"ks", 0.7, 0},
                                        {"ks", 0.3, 1},
                                        {"ks", 0.9, 2},
                                        {"n", s.n},
                                        {"d", s.d},
                                        {"h", s.h},
                                        {"phi_t", s.phi}});
    const std::string label = "n=" + std::to_string(int(s.n)) + " d=" + std::to_string(s.d).substr(0, 4) +
                              " h=" + std::to_string(s.h).substr(0, 3);
    expect_matches_reference(m, v, reference(m, v, s), 2e-4, label);
    expect_detects_five_percent(m, v, reference(m, v, s, 1.05), 2e-4, label);
  }
}

// Ngan et al.'s sharp lobe (n = 3000) is negligible at the shared pairs, so it is also compared
// where it lives, with 2·10⁶ points (the lobe is 0.009 rad wide; a shadow edge inside a cell
// costs up to ~4·10⁻⁵ of it: bound 10⁻⁴): pairs mirrored along the axis (wo_x = −wi_x in the cylinders' frame) whose
// cross-section angles put the specular element on the arc, at the shadow's edge (1.1, 0.83: the
// light at 1.1 rad lights the arc up to θ = 0.967), or on the arc's top and the gap (0.05, −0.05).
TEST(PoulinFournierReference, SharpLobeWhereItReflects) {
  const Model& m = model_by_name("poulin-fournier");
  const Surface s{3000, 0.18, 0.5, 0.3};
  const ParamValues v = values_of(m, {{"kd", 0.0}, {"ks", 1.0}, {"n", s.n}, {"d", s.d}, {"h", s.h}, {"phi_t", s.phi}});
  const Vec3d t(std::cos(s.phi), std::sin(s.phi), 0), b(-std::sin(s.phi), std::cos(s.phi), 0), z(0, 0, 1);
  double worst = 0;
  int count = 0;
  for (double along : {0.0, 0.3, -0.6})
    for (const auto& [ai, ao] : {std::pair{0.2, -0.4}, std::pair{-0.7, 0.1}, std::pair{1.1, 0.5}, std::pair{1.1, 0.83},
                                 std::pair{0.05, -0.05}, std::pair{1.3, -1.25}}) {
      const double r = std::sqrt(1 - along * along);
      const Vec3d wi = along * t + r * (std::sin(ai) * b + std::cos(ai) * z);
      const Vec3d wo = -along * t + r * (std::sin(ao) * b + std::cos(ao) * z);
      const double got = m.eval(v.channel(0), 0, wi, wo), want = brute_force_lobe(s, wi, wo, 2000000);
      EXPECT_GT(want, 0.0) << "(" << along << ", " << ai << ", " << ao << ")";
      EXPECT_NEAR(got, want, 1e-4 * want) << "(" << along << ", " << ai << ", " << ao << ")";
      worst = std::max(worst, std::abs(got - want) / want);
      ++count;
    }
  std::printf("[ reference ] poulin-fournier n=3000 d=0.18 h=0.5 at %d reflecting pairs: worst relative %.2e\n", count,
              worst);
}

}  // namespace
}  // namespace brdfkit::test::ref
