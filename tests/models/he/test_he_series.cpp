// The directional-diffuse series of He et al. 1991 (Eq. 78): the truncation rule of
// models/he_series.h against a long-double reference summed far past any significant term,
// and its rough limit.
#include <gtest/gtest.h>

#include <ceres/jet.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "brdfkit/models/he_series.h"

namespace brdfkit {
namespace {

// Σ_{m=1}^{M} e^{−g} gᵐ/(m!·m) e^{−c/m} in long double, M = g + 40√g + √c + 400: past the
// Poisson mode by 40 standard deviations and past the peak of e^{−c/m}/m, so what it leaves out
// is below 10⁻³⁰ of the sum for every (g, c) here.
long double reference_series(double g, double c) {
  const long double lg = std::log((long double)g);
  const int m_max = int(g + 40 * std::sqrt(g) + std::sqrt(c) + 400);
  long double sum = 0;
  for (int m = 1; m <= m_max; ++m)
    sum += std::exp(-(long double)g + m * lg - std::lgamma((long double)m + 1) - std::log((long double)m) -
                    (long double)c / m);
  return sum;
}

// The omitted part is bounded by the reported bound, which is ≤ 1e-6 (the model's tolerance),
// over roughness regimes from nearly smooth (g = 10⁻³) to very rough (g = 3000) and lobe
// offsets c = τ² v_xy²/4 from the specular peak (0) to far in the tail (10⁴).
TEST(HeSeries, TruncationErrorWithinItsBound) {
  double worst_error = 0, worst_bound = 0;
  int most_terms = 0;
  for (double g : {1e-3, 0.1, 1.0, 4.5, 30.0, 200.0, 3000.0}) {
    for (double c : {0.0, 0.5, 10.0, 300.0, 1e4}) {
      HeSeriesStats stats;
      const double s = he_series(g, c, 1e-6, &stats);
      const long double ref = reference_series(g, c);
      if (ref < 1e-300L) continue;  // underflows in double: nothing to compare
      const double rel = double(std::fabs((long double)s - ref) / ref);
      EXPECT_LE(rel, stats.omitted_bound + 1e-13) << "g " << g << " c " << c;
      EXPECT_LE(stats.omitted_bound, 1e-6) << "g " << g << " c " << c;
      EXPECT_LE(s, double(ref) * (1 + 1e-13)) << "truncation only removes positive terms";
      worst_error = std::max(worst_error, rel);
      worst_bound = std::max(worst_bound, stats.omitted_bound);
      most_terms = std::max(most_terms, stats.terms);
    }
  }
  std::printf("[ he series ] worst relative truncation error %.3g, worst bound %.3g, at most %d terms\n", worst_error,
              worst_bound, most_terms);
  EXPECT_LE(most_terms, 1000);  // O(√g) terms around the mode, not O(g)
}

// Doubles walk the series by term ratios (one exp a term), Jets by logs: the same sum and the same
// terms. The grid includes first terms that underflow (small g, c ≫ 1), where a ratio walk would
// multiply 0 by e^{c/2} = ∞ and never stop: doubles walk the ratios of the terms to the first there.
TEST(HeSeries, RatioWalkOfDoublesEqualsTheLogWalkOfJets) {
  using Jet = ceres::Jet<double, 1>;
  double worst = 0;
  for (double g : {1e-3, 0.01, 0.5, 3.0, 33.0, 300.0, 3000.0}) {
    for (double c : {0.0, 1.0, 50.0, 1200.0, 1500.0, 1e4}) {
      HeSeriesStats sd, sj;
      const double d = he_series(g, c, 1e-6, &sd);
      const Jet j = he_series(Jet(g, 0), Jet(c), 1e-6, &sj);
      ASSERT_TRUE(std::isfinite(d)) << "g " << g << " c " << c;
      EXPECT_EQ(sd.terms, sj.terms) << "g " << g << " c " << c;
      if (j.a == 0) {
        EXPECT_EQ(d, 0.0);
        continue;
      }
      const double rel = std::abs(d - j.a) / j.a;
      // Both walks share the first term; each log term of the Jet walk carries a rounding of its
      // exponent (−g + m ln g − ln m! ≈ 0 from terms of size g), ~g·ε = 7e-13 at g = 3000.
      EXPECT_LE(rel, 1e-11) << "g " << g << " c " << c;
      worst = std::max(worst, rel);
    }
  }
  std::printf("[ he series ] ratio walk vs log walk: worst relative difference %.3g\n", worst);
}

// The walk's ratios come eight at a time from glibc's vector exp: each is the scalar expression
// r_j = g j/(j+1)² e^{c/(j(j+1))} to within the vector exp's 4 ulp, upwards and downwards from any
// j, and a j below 1 (past a downward walk's end) gives r_1, finite.
TEST(HeSeries, TermRatioBlocksAreTheScalarRatios) {
  double worst = 0;
  for (double g : {1e-3, 0.7, 30.0, 3000.0}) {
    for (double c : {0.0, 3.0, 400.0, 5e4}) {
      for (int j0 : {1, 5, 37, 900}) {
        for (int step : {1, -1}) {
          double r[he_detail::kRatioBlock];
          he_detail::term_ratios(g, c, j0, step, r);
          for (int k = 0; k < he_detail::kRatioBlock; ++k) {
            const double j = std::max(j0 + step * k, 1);
            const double expected = g * j / ((j + 1) * (j + 1)) * std::exp(c / (j * (j + 1)));
            if (!std::isfinite(expected)) continue;  // e^{c/2} past double range: a downward walk reads ρ = 0
            ASSERT_TRUE(std::isfinite(r[k]));
            const double rel = std::abs(r[k] - expected) / expected;
            EXPECT_LE(rel, 1e-15) << "g " << g << " c " << c << " j " << j;
            worst = std::max(worst, rel);
          }
        }
      }
    }
  }
  std::printf("[ he series ] vector term ratios vs the scalar expression: worst relative difference %.3g\n", worst);
}

// Sums whose largest term lies below 1e-280 but which are still normal doubles: doubles walk the
// terms' ratios to the first one and scale back (he_series), to within the reported bound of the
// long-double reference.
TEST(HeSeries, SumsNearUnderflowMatchTheReference) {
  int compared = 0;
  double worst = 0;
  for (double g : {1e-3, 0.01, 0.3})
    for (int k = 0; k <= 400; ++k) {
      const double c = 1e3 * std::pow(10.0, k / 100.0);
      const long double ref = reference_series(g, c);
      if (!(ref > 1e-306L && ref < 1e-281L)) continue;
      HeSeriesStats stats;
      const double s = he_series(g, c, 1e-6, &stats);
      const double rel = double(std::fabs((long double)s - ref) / ref);
      EXPECT_LE(rel, stats.omitted_bound + 1e-12) << "g " << g << " c " << c;
      worst = std::max(worst, rel);
      ++compared;
    }
  std::printf("[ he series ] sums in (1e-306, 1e-281): %d compared, worst relative error %.3g\n", compared, worst);
  EXPECT_GE(compared, 10);
}

// log S where S lies below the smallest double (far from the peak of a rough surface, where the
// series table's nodes need it) and where it does not: the long-double reference has the range.
TEST(HeSeries, LogSeriesMatchesTheReferenceBelowTheSmallestDouble) {
  double worst = 0;
  int below = 0;
  for (double g : {2.0, 30.0, 700.0, 3000.0, 1e4}) {
    for (double u : {0.0, 3.0, 300.0, 1000.0}) {
      const long double ref = reference_series(g, u * g);
      const double err = std::abs(he_log_series(g, u * g, 1e-10) - double(std::log(ref)));
      // the truncation (≤ 1e-10) and the rounding of log t_start (terms of size g: ~g·ε)
      EXPECT_LE(err, 1e-10 + 1e-15 * g) << "g " << g << " c/g " << u;
      worst = std::max(worst, err);
      below += ref < 1e-308L;
    }
  }
  std::printf("[ he series ] log series vs reference: worst absolute difference %.3g (%d sums below 1e-308)\n", worst, below);
  EXPECT_GE(below, 3);
}

// A tighter tolerance shrinks the error with it (the rule is not a fixed term count).
TEST(HeSeries, ToleranceControlsTheError) {
  for (double tol : {1e-3, 1e-6, 1e-10}) {
    HeSeriesStats stats;
    const double s = he_series(200.0, 150.0, tol, &stats);
    const long double ref = reference_series(200.0, 150.0);
    EXPECT_LE(double(std::fabs((long double)s - ref) / ref), tol) << tol;
  }
}

// Rough limit (He 1991 §4, after Beckmann & Spizzichino 1963 §5.3): for g ≫ 1 the Poisson
// weights concentrate at m ≈ g and Σ → e^{−c/g}/g, the Gaussian slope distribution; the
// relative correction is O(1/g).
TEST(HeSeries, RoughLimitIsGaussian) {
  for (double g : {500.0, 2000.0}) {
    for (double u : {0.0, 0.5, 1.0, 2.0}) {
      const double c = u * g;
      const double s = he_series(g, c);
      const double limit = std::exp(-u) / g;
      EXPECT_NEAR(s / limit, 1.0, 6.0 / g) << "g " << g << " c/g " << u;
    }
  }
}

}  // namespace
}  // namespace brdfkit
