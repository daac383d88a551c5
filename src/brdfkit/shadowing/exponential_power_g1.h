#pragma once
// Holzschuch & Pacanowski 2015's tabulated G1 for the exponential power distribution
// P22(x) = p/(π σ² Γ(1/p)) exp(−(x/σ²)^p) (seed 004 Eq. 19/26, DESIGN.md §3): G1 depends on
// (σ tanθ, p) only (seed 004 §5.2), and §5.5 indexes the table by
//   a = 5/p   and   b = exp(−(1/(σ tanθ))^{1/20}),
// interpolated bilinearly. The nodes are filled from the direct Smith integral
// (shadowing/smith_integral.h) with σ = 1. The domain is the paper's, p ∈ [0.1, 5] (§5.8 bounds p
// by 5; its fits stay below 0.95); p outside is clamped to it.
#include <algorithm>
#include <cmath>
#include <vector>

#include "brdfkit/core/vec.h"
#include "brdfkit/shadowing/smith_integral.h"

namespace brdfkit {

class ExponentialPowerG1Table {
 public:
  static constexpr double kPMin = 0.1, kPMax = 5.0;
  // Nodes along a = 5/p and b; accuracy against the direct integral is checked in
  // tests/shadowing (test_exponential_power_g1.cpp states the measured error).
  static constexpr int kNa = 65, kNb = 513;

  // The shared table, built on first use (thread-safe).
  static const ExponentialPowerG1Table& instance();

  // G1 at z = σ tanθ ≥ 0 (0 gives 1, ∞ gives 0) and shape p; bilinear in (a, b), so Jets get
  // piecewise-constant derivatives in both arguments.
  template <class T> T g1(const T& sigma_tan_theta, const T& p) const {
    if (!(smith_detail::scalar(sigma_tan_theta) > 0.0)) return T(1);
    return g1_at(b_coordinate(sigma_tan_theta), p);
  }
  // The table's b coordinate of z > 0, in nodes: (kNb − 1) exp(−z^(−1/20)) (seed 004 §5.5).
  template <class T> static T b_coordinate(const T& sigma_tan_theta) {
    using std::exp;
    using std::pow;
    return exp(-pow(T(1) / sigma_tan_theta, T(1.0 / 20))) * T(kNb - 1);
  }
  // b_coordinate at the kDBlock values z[0 … kDBlock) with vector math (ndf/d_block.h's block and
  // bound; exponential_power_g1_block.cpp); z ≤ 0 gives a value g1_at must not be given.
  static void b_coordinate_block(const double* z, double* b);
  // G1 at table coordinate b (b_coordinate) and shape p.
  template <class T> T g1_at(const T& b, const T& p) const;

  // The slope density with σ = 1, templated for the direct integral.
  template <class T> struct UnitDistribution {
    double p;
    double norm;  // p / (π Γ(1/p))
    explicit UnitDistribution(double p_);
    T P22(const T& x) const {
      using std::exp;
      using std::pow;
      return T(norm) * exp(-pow(x, T(p)));  // seed 004 Eq. 19 with σ = 1
    }
  };
  // G1 by direct integration (the reference the table is built from).
  static double g1_direct(double sigma_tan_theta, double p);

 private:
  ExponentialPowerG1Table();
  std::vector<double> g1_;  // [ia * kNb + ib]
};

template <class T> ExponentialPowerG1Table::UnitDistribution<T>::UnitDistribution(double p_)
    : p(p_), norm(p_ / (kPi * std::tgamma(1.0 / p_))) {}

template <class T> T ExponentialPowerG1Table::g1_at(const T& b, const T& p) const {
  namespace sd = smith_detail;
  const T pc = sd::scalar(p) < kPMin ? T(kPMin) : (sd::scalar(p) > kPMax ? T(kPMax) : p);
  const T a = (T(5) / pc - T(5 / kPMax)) / T((5 / kPMin - 5 / kPMax) / (kNa - 1));  // seed 004 §5.5
  const int ia = std::clamp(static_cast<int>(sd::scalar(a)), 0, kNa - 2);
  const int ib = std::clamp(static_cast<int>(sd::scalar(b)), 0, kNb - 2);
  const T fa = a - T(double(ia)), fb = b - T(double(ib));
  const double* g = &g1_[size_t(ia) * kNb + ib];
  return (T(1) - fa) * ((T(1) - fb) * g[0] + fb * g[1]) + fa * ((T(1) - fb) * g[kNb] + fb * g[kNb + 1]);
}

}  // namespace brdfkit
