#pragma once
// What every reference test of tests/models/reference/ shares: the direction pairs a model is
// checked at, and the comparison of a catalogue model with a reference formula written in the
// test file itself (never with brdfkit's own model code).
//
// The pairs avoid the symmetric configurations that hide mistakes: θi ≠ θo everywhere (a swapped
// wi/wo or a cosine on the wrong direction changes the value), azimuth differences away from 0
// and π (a wrong half vector or a sign error in a tangent-plane term changes the value), absolute
// azimuths away from the axes (anisotropic models see the tangent frame), two near-mirror pairs
// (sharp lobes are non-negligible there) and three grazing pairs (θ ≥ 80°).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "brdfkit/core/vec.h"
#include "brdfkit/models/model.h"
#include "reference_math.h"

namespace brdfkit::test::ref {

struct DirectionPair {
  double theta_i, phi_i, theta_o, phi_o;  // degrees
  Vec3d wi() const { return spherical_direction(theta_i * kPi / 180, phi_i * kPi / 180); }
  Vec3d wo() const { return spherical_direction(theta_o * kPi / 180, phi_o * kPi / 180); }
};

inline const std::vector<DirectionPair>& direction_pairs() {
  static const std::vector<DirectionPair> pairs = {
      {20, 10, 50, 160},  {35, 40, 10, 190},  {60, 15, 25, 205}, {15, 30, 65, 130},
      {45, 30, 55, 240},  {5, 70, 30, 290},   {75, 20, 40, 170}, {40, 25, 42, 203},  // near mirror
      {30, 50, 33, 226},                                                             // near mirror
      {70, 100, 68, 275}, {85, 20, 80, 195},  {88, 35, 30, 220}, {50, 10, 86, 150},  // grazing: last three
  };
  return pairs;
}

// One parameter set: name = value for every channel, or for channel `channel` only (0, 1, 2).
struct Setting {
  std::string name;
  double value;
  int channel = -1;
};

inline ParamValues values_of(const Model& m, const std::vector<Setting>& settings) {
  ParamValues v = ParamValues::defaults(m.params());
  for (const Setting& s : settings) v.set(m.params(), s.name, s.value, s.channel);
  return v;
}

// The value of parameter `name` for channel c.
inline double param(const Model& m, const ParamValues& v, const std::string& name, int c) {
  const int i = find_param(m.params(), name);
  EXPECT_GE(i, 0) << "model '" << m.name() << "' has no parameter '" << name << "'";
  return i < 0 ? 0.0 : v.values[size_t(c)][size_t(i)];
}

// ρ_ref(c, wi, wo) of one parameter set, for the channel c.
using Reference = std::function<double(int c, const Vec3d& wi, const Vec3d& wo)>;

// The largest relative difference |model − ref| / |ref| over every direction pair and channel.
inline double max_relative_difference(const Model& model, const ParamValues& v, const Reference& reference) {
  double worst = 0;
  for (const DirectionPair& d : direction_pairs())
    for (int c = 0; c < 3; ++c) {
      const double got = model.eval(v.channel(c), c, d.wi(), d.wo()), want = reference(c, d.wi(), d.wo());
      worst = std::max(worst, std::abs(got - want) / std::max(std::abs(want), 1e-300));
    }
  return worst;
}

// Compares `model` (through its runtime Model::eval) with `reference` at every direction pair
// and channel; |model − ref| ≤ rel_tol·|ref| (plus 1e-300 so exact zeros compare). Prints the
// largest relative difference seen, so the bound each test asserts stays visible.
inline void expect_matches_reference(const Model& model, const ParamValues& v, const Reference& reference,
                                     double rel_tol, const std::string& label) {
  for (const DirectionPair& d : direction_pairs()) {
    const Vec3d wi = d.wi(), wo = d.wo();
    for (int c = 0; c < 3; ++c) {
      const double got = model.eval(v.channel(c), c, wi, wo);
      const double want = reference(c, wi, wo);
      EXPECT_LE(std::abs(got - want), rel_tol * std::abs(want) + 1e-300)
          << model.name() << " [" << label << "] channel " << c << " at (θi, φi, θo, φo) = (" << d.theta_i << ", "
          << d.phi_i << ", " << d.theta_o << ", " << d.phi_o << ") deg: model " << got << ", reference " << want;
    }
  }
  std::printf("[ reference ] %-34s %-26s worst relative difference %.2e (bound %.0e)\n",
              std::string(model.name()).c_str(), label.c_str(), max_relative_difference(model, v, reference), rel_tol);
}

// The comparison above must be able to fail: with the lobe's normalization off by 5 % in the
// reference, the model must differ from it by more than the bound somewhere — by most of the
// 5 % (≥ 4 %, where the lobe dominates) and by at least twice the bound.
inline void expect_detects_five_percent(const Model& model, const ParamValues& v, const Reference& scaled_reference,
                                        double rel_tol, const std::string& label) {
  const double worst = max_relative_difference(model, v, scaled_reference);
  EXPECT_GT(worst, std::max(0.04, 2 * rel_tol))
      << model.name() << " [" << label << "]: a reference with its lobe scaled by 1.05 still matches within the bound";
}

inline Vec3d half_vector(const Vec3d& wi, const Vec3d& wo) { return (wi + wo).normalized(); }

}  // namespace brdfkit::test::ref
