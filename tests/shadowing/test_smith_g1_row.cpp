// The G1 row (shadowing/smith_g1_row.h) against smith_g1 for every distribution of
// ndf/distributions.h whose Λ is numeric: random parameters over each one's whole box
// (log-uniform where its table axis is logarithmic) and θ over the hemisphere; the worst |ΔG1|
// is printed and bounded. A row of other parameters must not pass (the control). Its block
// evaluation gives g1's values to the bit, on runs of repeated cosines and on scattered ones.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "brdfkit/models/cook_torrance.h"
#include "brdfkit/ndf/d_block.h"
#include "brdfkit/ndf/distributions.h"
#include "brdfkit/shadowing/smith_g1_row.h"

namespace brdfkit {
namespace {

template <template <class> class Ndf> std::vector<double> random_params(std::mt19937_64& rng) {
  const ParamTable table = Ndf<double>::params();
  const auto axes = SmithShape<Ndf>::axes();
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> p(table.size());
  for (size_t k = 0; k < table.size(); ++k) {
    const double lo = table[k].lower, hi = table[k].upper;
    const bool log_axis = k < axes.size() && axes[k].log_scale && lo > 0;
    p[k] = log_axis ? lo * std::pow(hi / lo, u(rng)) : lo + (hi - lo) * u(rng);
  }
  return p;
}

// Worst |row − smith_g1| over n parameter sets × 200 angles; with `other`, the row of a second
// random parameter set is compared instead (the control).
template <template <class> class Ndf> double worst_error(int n, bool other = false) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0;
  for (int i = 0; i < n; ++i) {
    const std::vector<double> p = random_params<Ndf>(rng), q = random_params<Ndf>(rng);
    const Ndf<double> ndf(p.data()), row_ndf(other ? q.data() : p.data());
    const SmithG1Row& row = smith_g1_row(row_ndf);
    for (int k = 0; k < 200; ++k) {
      const double c = k == 0 ? 1.0 : std::cos(0.5 * kPi * std::sqrt(u(rng)));
      worst = std::max(worst, std::abs(row.g1(c) - smith_g1(ndf, c)));
    }
  }
  return worst;
}

TEST(SmithG1Row, MatchesSmithG1ForEveryNumericLambda) {
  int checked = 0;
  Distributions::for_each([&]<template <class> class D>() {
    if constexpr (kG1FromRow<D>) {
      const double e = worst_error<D>(60);
      std::printf("  %-18s max |dG1| row vs smith_g1: %.3g\n", std::string(D<double>::kName).c_str(), e);
      EXPECT_LT(e, 1e-6) << D<double>::kName;
      EXPECT_GT(worst_error<D>(20, true), 1e-3) << D<double>::kName << ": the control must fail";
      ++checked;
    }
  });
  EXPECT_GE(checked, 8);  // every distribution but Beckmann and GGX (closed forms)
}

TEST(SmithG1Row, EdgesAndCache) {
  const double p = 0.3;
  const SchlickRational<double> schlick(&p);
  const SmithG1Row& row = smith_g1_row(schlick);
  EXPECT_EQ(row.g1(1.0), 1.0);
  EXPECT_EQ(row.g1(0.0), 0.0);
  EXPECT_EQ(row.g1(-0.2), 0.0);
  EXPECT_EQ(row.g1(0.95), smith_g1(schlick, 0.95));  // inside the support edge: G1 = 1 exactly
  const double q = 0.5;
  const SchlickRational<double> other(&q);
  const double a = row.g1(0.3);
  const double b = smith_g1_row(other).g1(0.3);
  EXPECT_NE(a, b);
  EXPECT_EQ(smith_g1_row(schlick).g1(0.3), a);  // both parameter sets stay cached
}

TEST(SmithG1Row, BlockEqualsG1ToTheBitOnRunsAndOnScatteredCosines) {
  std::mt19937_64 rng(43);
  std::uniform_real_distribution<double> u(0, 1);
  const double p = 0.3, sgd[2] = {0.2, 1.1};
  const SchlickRational<double> schlick(&p);  // G1 = 1 inside its support edge
  const Sgd<double> sgd_ndf(sgd);
  for (const SmithG1Row* row : {&smith_g1_row(schlick), &smith_g1_row(sgd_ndf)}) {
    std::vector<double> scattered(kDBlock), runs(kDBlock);
    for (std::size_t k = 0; k < kDBlock; ++k) scattered[k] = 1.2 * u(rng) - 0.1;  // below the horizon too
    for (double edge : {0.0, 1.0, -0.0, std::nan("")}) scattered[size_t(u(rng) * kDBlock)] = edge;
    for (std::size_t k = 0; k < kDBlock; ++k) runs[k] = k % 64 == 0 ? std::cos(1.6 * u(rng)) : runs[k - 1];
    for (const auto* cosines : {&scattered, &runs}) {
      std::vector<double> out(kDBlock);
      row->g1_block(cosines->data(), out.data());
      for (std::size_t k = 0; k < kDBlock; ++k) {
        const double want = row->g1((*cosines)[k]);
        ASSERT_TRUE(out[k] == want || (std::isnan(out[k]) && std::isnan(want)))
            << "cosine " << (*cosines)[k] << ": " << out[k] << " vs " << want;
      }
    }
  }
}

}  // namespace
}  // namespace brdfkit
