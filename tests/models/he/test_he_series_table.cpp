// The table of He et al. 1991's Eq. 78 series (models/he_series_table.h): inside its domain it
// agrees with the series summed to 1e-12 within its stated 1e-6 (worst measured over random and
// edge points, printed), outside it is the series itself, its block look-up agrees with the scalar
// one, and the model evaluated through it agrees with the model summing its series.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "brdfkit/core/vec.h"
#include "brdfkit/models/he_series.h"
#include "brdfkit/models/he_series_table.h"
#include "brdfkit/models/he_torrance.h"

namespace brdfkit {
namespace {

TEST(HeSeriesTable, AgreesWithTheSeriesOverItsDomain) {
  const HeSeriesTable& table = HeSeriesTable::get();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  // The worst relative difference and where, in the near rows (c/g ≤ 1000), the far ones and the
  // low run (g < 0.5).
  struct Worst {
    double rel = 0, g = 0, c = 0;
  } worst[3];
  int underflows = 0;
  auto check = [&](double g, double c) {
    ASSERT_TRUE(table.covers(g, c)) << g << " " << c;
    const double want = he_series(g, c, 1e-12), got = table(g, c);
    if (want < 1e-290) {  // far from the peak of a rough surface S underflows: no relative error
      ++underflows;
      return;
    }
    const double rel = std::abs(got / want - 1);
    Worst& w = worst[g < 0.5 ? 2 : c > 1000 * g];
    if (rel > w.rel) w = {rel, g, c};
  };
  for (int k = 0; k < 100000; ++k) {  // the near rows
    const double g = 0.5 * std::pow(1e4 / 0.5, u(rng)), y = std::expm1(u(rng) * std::log1p(1000.0));
    check(g, g * y);
  }
  for (int k = 0; k < 30000; ++k) {  // the far rows
    const double g = 0.5 * std::pow(1e4 / 0.5, u(rng)), y = 1000 * std::pow(100.0, u(rng));
    check(g, g * y);
  }
  for (int k = 0; k < 100000; ++k) {  // the low run
    const double g = 1e-3 * std::pow(0.5 / 1e-3, u(rng)), c = std::expm1(u(rng) * std::log1p(1e5 * g));
    check(std::min(g, 0.4999999), c);
  }
  for (double g : {1e-3, 0.0010001, 0.01, 0.2, 0.4999, 0.5, 0.5001, 2.0, 99.5, 3200.0, 1e4})  // the edges
    for (double y : {0.0, 1e-9, 0.37, 99.9, 299.9, 999.9, 1000.0, 1000.0001, 1e4, 99999.0, 1e5}) check(g, g * y);
  const char* run[3] = {"near", "far", "low"};
  for (int r = 0; r < 3; ++r)
    std::printf("He series table, %s rows: worst relative difference to the series %.3g at g = %.6g, c = %.6g\n",
                run[r], worst[r].rel, worst[r].g, worst[r].c);
  std::printf("He series table: %d points underflow\n", underflows);
  EXPECT_LT(worst[0].rel, 5e-7);
  EXPECT_LT(worst[1].rel, 5e-7);
  EXPECT_LT(worst[2].rel, 5e-7);
}

// The build sums the nodes once and compiles them in (cmake/generators/he_series_table.cpp): they
// are the nodes compute_nodes sums here. The generator is never instrumented; where the library is
// (the sanitizers' build), or a machine's vector exp is another variant, each of a node's few hundred
// ratios may round differently: 1e-12 in r = log S + … relative to max(1, |r|), since far rows
// reach |r| ≈ 3·10⁴ where S underflows and an ulp there is 3.6e-12 (the sanitizers' build: 1 ulp
// at five such nodes, 1.1e-13 in the near rows; 0 otherwise).
TEST(HeSeriesTable, CompiledInNodesAreTheComputedNodes) {
  const HeSeriesTable::Nodes want = HeSeriesTable::compute_nodes();
  const std::span<const double> got = HeSeriesTable::get().nodes(), got_low = HeSeriesTable::get().low_nodes();
  ASSERT_EQ(got.size(), want.r.size());
  ASSERT_EQ(got.size(), size_t(want.columns) * size_t(want.rows + want.far_rows));
  ASSERT_EQ(got_low.size(), want.low.size());
  ASSERT_EQ(got_low.size(), size_t(want.low_columns) * size_t(want.low_rows));
  double worst = 0;
  for (std::size_t k = 0; k < got.size(); ++k)
    worst = std::max(worst, std::abs(got[k] - want.r[k]) / std::max(1.0, std::abs(want.r[k])));
  for (std::size_t k = 0; k < got_low.size(); ++k)
    worst = std::max(worst, std::abs(got_low[k] - want.low[k]) / std::max(1.0, std::abs(want.low[k])));
  std::printf("He series table: %zu compiled-in nodes, worst difference to the computed nodes %.3g (relative to "
              "max(1, |r|))\n",
              got.size() + got_low.size(), worst);
  EXPECT_LE(worst, 1e-12);
}

TEST(HeSeriesTable, OutsideItsDomainSumsTheSeries) {
  const HeSeriesTable& table = HeSeriesTable::get();
  for (const auto& [g, c] :
       {std::pair{5e-4, 3.0}, std::pair{9.99e-4, 0.0}, std::pair{0.3, 3.1e4}, std::pair{2e4, 10.0}, std::pair{50.0, 5.00001e6}}) {
    EXPECT_FALSE(table.covers(g, c)) << g << " " << c;
    EXPECT_EQ(table(g, c), he_series(g, c, HeSeriesTable::kSummedTolerance)) << g << " " << c;
  }
}

// The block look-up (vector log, log1p and exp) against the scalar one: within 1e-12 relative
// inside the near rows and 1e-11 in the far ones (there log S moves by up to ~700 per unit of
// q = log(c/g), which turns the vector log's 4 ulp of q into ~5e-12 of S), the same summed series
// outside the domain, and a value that does not depend on the lane it is computed in.
TEST(HeSeriesTable, BlockAgreesWithTheScalarLookUpInEveryLane) {
  const HeSeriesTable& table = HeSeriesTable::get();
  constexpr std::size_t kB = HeSeriesTable::kBlock;
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> g, c;
  for (int k = 0; k < 20000; ++k) {  // g from 10⁻⁴ to 2·10⁴ and c/g to 3·10⁵: inside and outside
    const double gk = 1e-4 * std::pow(2e8, u(rng));
    g.push_back(gk);
    c.push_back(gk * std::expm1(u(rng) * std::log1p(3e5)));
  }
  for (double gk : {0.5, 1e4})  // the edges of the domain
    for (double y : {0.0, 1000.0, 1e5}) g.push_back(gk), c.push_back(gk * y);
  while (g.size() % kB) g.push_back(5.0), c.push_back(1.0);
  // S of every pair through blocks, with the pairs first rotated by `shift` lanes.
  auto blocked = [&](int shift) {
    std::vector<double> gs(g), cs(c), s(g.size());
    std::rotate(gs.begin(), gs.begin() + shift, gs.end());
    std::rotate(cs.begin(), cs.begin() + shift, cs.end());
    for (std::size_t b = 0; b < gs.size(); b += kB) table.block(gs.data() + b, cs.data() + b, s.data() + b);
    std::rotate(s.rbegin(), s.rbegin() + shift, s.rend());
    return s;
  };
  const std::vector<double> s = blocked(0), shifted = blocked(1);
  double worst[2] = {0, 0};  // near rows, far rows
  int outside = 0;
  for (std::size_t k = 0; k < g.size(); ++k) {
    ASSERT_EQ(s[k], shifted[k]) << "lane dependence at g " << g[k] << " c " << c[k];
    const double want = table(g[k], c[k]);
    if (!table.covers(g[k], c[k])) {
      ASSERT_EQ(s[k], want) << "outside the domain: g " << g[k] << " c " << c[k];
      ++outside;
    } else if (want > 1e-290) {  // S a normal double (as in AgreesWithTheSeriesOverItsDomain)
      double& w = worst[c[k] > 1000 * g[k]];
      w = std::max(w, std::abs(s[k] / want - 1));
    }
  }
  std::printf("He series table: block look-up vs scalar, worst relative %.3g near, %.3g far "
              "(%d pairs outside the domain summed)\n",
              worst[0], worst[1], outside);
  EXPECT_LT(worst[0], 1e-12);
  EXPECT_LT(worst[1], 1e-11);
  EXPECT_GT(outside, 1000);
}

// He's three channels share c/g at a pair (their g and c both scale with k²): one set of rows
// serves every channel's g, each value within the block look-up's bounds of the scalar look-up at
// c = ratio · g inside the domain, and that series summed outside it.
TEST(HeSeriesTable, RowsSharedAtOneRatioServeEveryChannelsG) {
  const HeSeriesTable& table = HeSeriesTable::get();
  constexpr std::size_t kB = HeSeriesTable::kBlock;
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(0, 1);
  double worst[2] = {0, 0};  // near rows, far rows
  int outside = 0;
  for (int b = 0; b < 300; ++b) {
    double ratio[kB], g[3][kB], s[kB];
    for (std::size_t k = 0; k < kB; ++k) {
      ratio[k] = std::expm1(u(rng) * std::log1p(3e5));  // c/g to 3·10⁵: near and far rows, and outside
      g[0][k] = 1e-4 * std::pow(2e8, u(rng));
      for (int ch = 1; ch < 3; ++ch) {  // g ∝ k² = (2π/λ)²
        const double lambda_ratio = kChannelWavelengthUm[0] / kChannelWavelengthUm[ch];
        g[ch][k] = g[0][k] * lambda_ratio * lambda_ratio;
      }
    }
    HeSeriesTable::Rows rows;
    table.rows(ratio, rows);
    for (const auto& gc : g) {
      table.block_at(rows, gc, s);
      for (std::size_t k = 0; k < kB; ++k) {
        const double c = ratio[k] * gc[k], want = table(gc[k], c);
        if (!table.covers(gc[k], c)) {
          ASSERT_EQ(s[k], he_series(gc[k], c, HeSeriesTable::kSummedTolerance)) << "g " << gc[k] << " c " << c;
          ++outside;
        } else if (want > 1e-290) {
          double& w = worst[ratio[k] > 1000];
          w = std::max(w, std::abs(s[k] / want - 1));
        }
      }
    }
  }
  std::printf("He series table: shared rows vs scalar, worst relative %.3g near, %.3g far (%d outside the domain)\n",
              worst[0], worst[1], outside);
  EXPECT_LT(worst[0], 1e-12);
  EXPECT_LT(worst[1], 1e-11);
  EXPECT_GT(outside, 1000);
}

// Outside its domain the table sums the series, whose value jumps where its term count changes.
// The fitter's forward differences step by 1e-6 relative (fit/engine/finite_difference.h), so a
// jump must stay below 1e-9 of S: it then errs by ≤ 1e-3 of a unit slope of log S in log g.
TEST(HeSeriesTable, OutsideItsDomainJumpsTooLittleForForwardDifferences) {
  const HeSeriesTable& table = HeSeriesTable::get();
  double worst = 0;
  for (const auto& [g0, c] :
       {std::pair{8e-4, 2.0}, std::pair{4e-4, 40.0}, std::pair{1e-4, 10.0}, std::pair{1.2e4, 10.0}}) {
    ASSERT_FALSE(table.covers(g0, c));
    auto terms = [c = c](double g) {
      HeSeriesStats stats;
      he_series(g, c, HeSeriesTable::kSummedTolerance, &stats);
      return stats.terms;
    };
    // Bisect [g0, 1.5 g0] down to a change of the term count.
    double lo = g0, hi = 1.5 * g0;
    const int n0 = terms(lo);
    ASSERT_NE(terms(hi), n0) << g0 << " " << c;
    while (hi - lo > 1e-13 * lo) {
      const double mid = 0.5 * (lo + hi);
      (terms(mid) == n0 ? lo : hi) = mid;
    }
    const double jump = std::abs(table(hi, c) / table(lo, c) - 1);
    EXPECT_LE(jump, 1e-9) << "g " << lo << " c " << c;
    worst = std::max(worst, jump);
  }
  std::printf("He series table: worst jump of S where the summed series changes its term count %.3g\n", worst);
}

// The model's directional-diffuse term through the table against the same term with its series
// summed (a tolerance tighter than the table's sends it there), over roughnesses whose g spans the
// table and beyond, at random pairs.
TEST(HeSeriesTable, ModelThroughTheTableAgreesWithTheSummedSeries) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0;
  int tabulated = 0;
  for (double sigma0 : {0.05, 0.3, 0.8, 1.9})
    for (double tau : {0.5, 3.0, 20.0}) {
      const double p[6] = {0.1, 1.0, sigma0, tau, 1.5, 0.2};
      for (int k = 0; k < 300; ++k) {
        const Vec3d wi = spherical_direction(std::acos(u(rng)), 2 * kPi * u(rng)), wo = spherical_direction(std::acos(u(rng)), 2 * kPi * u(rng));
        for (int c = 0; c < 3; ++c) {
          const double fast = HeTorrance::directional_diffuse(p, c, wi, wo);
          const double summed = HeTorrance::directional_diffuse(p, c, wi, wo, nullptr, 1e-9);
          if (!(summed > 1e-280)) continue;
          worst = std::max(worst, std::abs(fast / summed - 1));
          const double k_wave = 2 * kPi / HeTorrance::wavelength_um(c);
          tabulated += HeSeriesTable::get().covers(std::pow(k_wave * sigma0 * (wi.z() + wo.z()), 2), 0.0);
        }
      }
    }
  std::printf("He through its series table vs summed: worst relative %.3g (%d evaluations with g in the table's range)\n", worst,
              tabulated);
  EXPECT_GT(tabulated, 2000);
  EXPECT_LT(worst, 1.5e-6);  // the table's 1e-6 and the series' 1e-6 truncation
}

}  // namespace
}  // namespace brdfkit
