// The scan that chooses start 0 of a fit (fit/start_scan.h): its grids, that it never
// returns a point worse than the defaults, that it finds the basin a local solver from the
// defaults misses, and that it is deterministic.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "brdfkit/fit/engine/start_scan.h"

namespace brdfkit::fit {
namespace {

ParamSpec spec(double lower, double upper, double def) { return {"x", lower, upper, def, Scope::Shared, false, ""}; }

TEST(StartScanGrid, WidthsAreLogSpacedCellCentresInsideTheBounds) {
  const std::vector<double> g = scan_grid(spec(0.001, 2, 0.2));  // a Beckmann α
  // 3.3 decades at 4 points per decade: 13 points, each a factor (2/0.001)^(1/13) apart.
  ASSERT_EQ(g.size(), 13u);
  const double ratio = std::pow(2000.0, 1.0 / 13);
  EXPECT_NEAR(g.front(), 0.001 * std::sqrt(ratio), 1e-15);
  EXPECT_NEAR(g.back(), 2 / std::sqrt(ratio), 1e-12);
  for (size_t i = 1; i < g.size(); ++i) EXPECT_NEAR(g[i] / g[i - 1], ratio, 1e-12);
}

TEST(StartScanGrid, ExponentsFromZeroStartSixDecadesBelowTheUpperBound) {
  const std::vector<double> g = scan_grid(spec(0, 1e6, 50));  // a Blinn-Phong N
  ASSERT_EQ(g.size(), 24u);                                    // 6 decades, capped at 24 points
  EXPECT_GT(g.front(), 1.0);
  EXPECT_LT(g.front(), 1.4);
  EXPECT_LT(g.back(), 1e6);
}

TEST(StartScanGrid, NarrowRangesAreLinearAndInfiniteOnesAreNotScanned) {
  const std::vector<double> p = scan_grid(spec(0, 1.95, 0.5));  // SGD p
  ASSERT_EQ(p.size(), 8u);
  for (size_t i = 0; i < p.size(); ++i) EXPECT_NEAR(p[i], (i + 0.5) / 8 * 1.95, 1e-15);
  EXPECT_EQ(scan_grid(spec(-10, 10, 0)).size(), 8u);  // Bagher F0
  EXPECT_TRUE(scan_grid(spec(0, INFINITY, 1)).empty());
  EXPECT_TRUE(scan_grid(spec(0.5, 0.5, 0.5)).empty());
}

// A width with a shallow local minimum at the default 0.2 and the deep one at 0.01: in log α the
// cost is a double well; a local solver from 0.2 stays there, the scan moves the start to the
// deep well's basin.
double double_well(double alpha) {
  const double t = std::log10(alpha);  // wells at t = log10(0.2) ≈ −0.7 and t = −2
  return 1.0 - 0.3 * std::exp(-std::pow((t + 0.699) / 0.3, 2)) - std::exp(-std::pow((t + 2) / 0.3, 2));
}

TEST(StartScan, FindsTheDeepBasinAndNeverReturnsAWorsePointThanTheStart) {
  const ParamTable table = {spec(0.001, 2, 0.2)};
  const auto cost = [](const std::vector<double>& x) { return double_well(x[0]); };
  const StartScan s = scan_start(table, {0}, {0.2}, cost);
  EXPECT_EQ(s.points, 1 + 13);  // one parameter: one sweep
  EXPECT_LT(s.cost, double_well(0.2));
  EXPECT_GT(s.x[0], 0.01 / std::pow(2000.0, 1.0 / 13));  // within one grid step of the deep minimum
  EXPECT_LT(s.x[0], 0.01 * std::pow(2000.0, 1.0 / 13));
  // A start better than every grid point is kept.
  const StartScan kept = scan_start(table, {0}, {0.01}, cost);
  EXPECT_EQ(kept.x[0], 0.01);
  EXPECT_EQ(kept.cost, double_well(0.01));
}

// Per-channel variables of one parameter move together, then each alone, so that channels may
// end on different grid points (He's η: one channel's best index lies above 1, another's below);
// non-finite costs never win; the result is the same on every call.
TEST(StartScan, ChannelsMoveTogetherThenEachAloneNonFiniteLosesAndTheResultIsDeterministic) {
  const ParamTable table = {spec(0, 1, 0.05), spec(0, 1e6, 100)};  // Rs (3 channels), N
  const std::vector<int> var_param = {0, 0, 0, 1};
  std::vector<std::vector<double>> calls;
  const auto cost = [&](const std::vector<double>& x) {
    calls.push_back(x);
    if (x[3] > 1e4) return std::nan("");
    return std::pow(x[0] - 0.3, 2) + std::pow(x[1] - 0.8, 2) + std::pow(x[2] - 0.1, 2) +
           std::pow(std::log10(x[3]) - 2.5, 2);
  };
  const StartScan a = scan_start(table, var_param, {0.05, 0.05, 0.05, 100}, cost);
  EXPECT_EQ(a.points, int(calls.size()));
  // The joint sweep first: the 8 grid points of Rs with the three channels equal.
  ASSERT_GT(calls.size(), 9u);
  for (size_t i = 1; i <= 8; ++i) {
    EXPECT_EQ(calls[i][0], calls[i][1]);
    EXPECT_EQ(calls[i][1], calls[i][2]);
  }
  EXPECT_LE(a.x[3], 1e4);
  EXPECT_NEAR(a.x[0], 0.3125, 1e-15);  // each channel at the grid point nearest its minimum
  EXPECT_NEAR(a.x[1], 0.8125, 1e-15);
  EXPECT_NEAR(a.x[2], 0.0625, 1e-15);
  EXPECT_NEAR(std::log10(a.x[3]), 2.5, 0.125 + 1e-12);
  calls.clear();
  const StartScan b = scan_start(table, var_param, {0.05, 0.05, 0.05, 100}, cost);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.cost, b.cost);
}

// Two correlated parameters (a valley along x = y): the second sweep follows the valley further
// than one sweep can.
TEST(StartScan, SecondSweepImprovesACorrelatedValley) {
  const ParamTable table = {spec(0, 1, 0.1), spec(0, 1, 0.1)};
  const auto cost = [](const std::vector<double>& x) {
    return 10 * std::pow(x[0] - x[1], 2) + std::pow(x[0] + x[1] - 1.5, 2);
  };
  const StartScan one = scan_start(table, {0, 1}, {0.1, 0.1}, cost, 1);
  const StartScan two = scan_start(table, {0, 1}, {0.1, 0.1}, cost, 2);
  EXPECT_EQ(one.points, 1 + 16);
  EXPECT_LT(two.cost, one.cost);
}

}  // namespace
}  // namespace brdfkit::fit
