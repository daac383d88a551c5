#pragma once
// Bagher et al. 2012's closed-form approximation of the Smith G1 of the SGD distribution
// (seed 000 Eq. 9; DESIGN.md §4):
//   G1(θ) ≈ 1 + λ (1 − exp(c (θ − θ0)^k))  for θ > θ0,   1 otherwise,
//   θ0 = π/2 − (log(1 + 1/λ)/c)^{1/k},   which makes G1(π/2) = 0 exactly.
// The paper fits (λ, c, k) per (α, p) by Levenberg-Marquardt to the numerically integrated G1;
// fit_bagher_g1 does the same with Ceres (automatic derivatives).
#include <cmath>
#include <span>
#include <vector>

#include "brdfkit/core/vec.h"

namespace brdfkit {

template <class T> struct BagherG1 {
  T lambda;
  T c;
  T k;
  T theta0;

  // θ0 from (λ, c, k) (seed 000 Eq. 9).
  static T theta0_of(const T& lambda, const T& c, const T& k) {
    using std::log;
    using std::pow;
    return T(kPi / 2) - pow(log(T(1) + T(1) / lambda) / c, T(1) / k);
  }
  BagherG1(const T& lambda_, const T& c_, const T& k_) : lambda(lambda_), c(c_), k(k_), theta0(theta0_of(lambda_, c_, k_)) {}
  // With a published θ0 (bagher2012-sgd.json publishes θ0 next to λ, c, k).
  BagherG1(const T& lambda_, const T& c_, const T& k_, const T& theta0_) : lambda(lambda_), c(c_), k(k_), theta0(theta0_) {}

  T eval(const T& theta) const {
    using std::exp;
    using std::pow;
    if (!(theta > theta0)) return T(1);
    return T(1) + lambda * (T(1) - exp(c * pow(theta - theta0, k)));  // seed 000 Eq. 9
  }
};

// The paper's "L2 error" (seed 000 §4.3: "negligible, mostly below 10⁻⁵"; Fig. 5: "below 10⁻⁵")
// is not defined there. Read as the SUM of squared residuals over the tabulated G1 values, with the
// table at 1° (θj = j + ½ degrees, 90 angles, the angular resolution of the MERL data the paper
// fits). Evidence, from the 300 published channel fits (data/published-fits/bagher2012-sgd.json)
// against our numeric G1: this sum is below 1e-5 for 244/300 ("mostly below"); over 120 angles for
// 223/300; the mean of squares (or ∫Δ² dθ) is below 1e-5 for all 300 with a maximum of 1e-6 (the
// paper would not then say "mostly"), and the norm sqrt(∫Δ² dθ) for none. The count of angles is
// the one free choice: Eq. 9 cannot reach 1e-5 over 120 angles at α = 0.05, p = 1.7 (its global
// minimum there is 1.165e-5, checked with 4 620 Levenberg-Marquardt starts and bounds w ≤ 1000,
// k ≤ 1e6), while the 1° sum (= ∫Δ² dθ / 1°) stays below it on the whole range.
struct BagherG1Fit {
  double lambda = 0, c = 0, k = 0, theta0 = 0;
  double sum_sq = 0;  // Σ residual² over the fitted angles: the paper's "L2 error" on a 1° table (above)
  double rms = 0;     // sqrt(sum_sq / n)
  int n = 0;
  BagherG1<double> model() const { return {lambda, c, k, theta0}; }
};

// The default angle set: n angles at the centres of equal cells of [0, π/2], θj = (j + ½) π/(2n);
// n = 90 is the 1° table of the paper's error measure.
std::vector<double> bagher_g1_angles(int n = 90);

// Least-squares fit of (λ, c, k) to target values g1[j] at angles theta[j] (radians in [0, π/2]).
// Internally parameterized by (log λ, w = π/2 − θ0, log k), where G1 = 1 + λ(1 − (1 + 1/λ)^(((θ−θ0)/w)^k))
// is the same function with well-conditioned parameters; a coarse grid search picks the starts of
// Levenberg-Marquardt (Ceres, automatic derivatives), the best result is kept.
// Throws InputError on empty or mismatched input.
BagherG1Fit fit_bagher_g1(std::span<const double> theta, std::span<const double> g1);

}  // namespace brdfkit
