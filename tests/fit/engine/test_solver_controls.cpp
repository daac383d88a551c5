// What steers the solver between starts and levels: the subsampling strides (fit/sample_stride.h),
// the stall stop (fit/stall_stop.h) and what a level asks of its objective (fit/ceres_adapter.h).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdio>
#include <memory>
#include <numeric>
#include <set>
#include <vector>

#include "brdfkit/fit/engine/ceres_adapter.h"
#include "brdfkit/fit/engine/sample_stride.h"
#include "brdfkit/fit/engine/stall_stop.h"

namespace brdfkit::fit {
namespace {

// A domain row of 90 θd × 180 Δφ samples (an RGL grid chunk): every stride the fitter uses visits
// every Δφ column, the mirror plane's included. The old level strides (4, 16, 64) visited 45.
TEST(SampleStride, CoarseStridesVisitEveryAzimuthColumn) {
  EXPECT_EQ(coprime_stride(64), 67u);
  EXPECT_EQ(coprime_stride(16), 17u);
  EXPECT_EQ(coprime_stride(4), 7u);
  EXPECT_EQ(coprime_stride(0), 1u);
  auto columns = [](size_t s) {
    std::set<size_t> seen;
    for (size_t k = 0; k < 90 * 180; k += s) seen.insert(k % 180);
    return seen.size();
  };
  for (size_t s = 1; s <= 80; ++s) {
    const size_t c = coprime_stride(s);
    EXPECT_GE(c, s);
    EXPECT_EQ(std::gcd(c, size_t(30)), 1u) << s;
    EXPECT_EQ(columns(c), 180u) << "stride " << c;
  }
  EXPECT_EQ(columns(4), 45u);  // what the old stride saw
}

ceres::IterationSummary step(int iteration, double cost, bool successful = true) {
  ceres::IterationSummary s;
  s.iteration = iteration;
  s.cost = cost;
  s.step_is_successful = successful;
  return s;
}

// Stops after `window` successful steps that together lowered the cost by < `relative` of it,
// under either rule; failed steps (the trust region shrinking) do not count, and a fit still
// improving goes on.
TEST(StallStop, StopsOnlyWhenAWindowGainedLessThanItsShare) {
  for (const StallRule* rule : {&kCrawl, &kSettled}) {
    // Per step half the rule's share: the crawl's 1e-5 a step is twice the settled rule's share
    // (5e-6), so each case stops by its own rule.
    const double gain = 0.5 * rule->relative / rule->window;
    StallStop crawl;
    EXPECT_EQ(crawl(step(0, 1.0)), ceres::SOLVER_CONTINUE);
    int it = 1;
    for (int k = 0; k < rule->window; ++k) EXPECT_EQ(crawl(step(it++, 1.0 - gain * (k + 1))), ceres::SOLVER_CONTINUE);
    for (int k = 0; k < 20; ++k) EXPECT_EQ(crawl(step(it++, 0.5, false)), ceres::SOLVER_CONTINUE);  // failed steps
    EXPECT_EQ(crawl(step(it++, 1.0 - gain * (rule->window + 1))), ceres::SOLVER_TERMINATE_SUCCESSFULLY);
    EXPECT_EQ(crawl.stalled(), rule);
  }

  StallStop improving;  // 1e-3 relative per step: ≥ 10× either threshold
  double cost = 1.0;
  for (int i = 1; i < 200; ++i) {
    cost *= 1 - 1e-3;
    ASSERT_EQ(improving(step(i, cost)), ceres::SOLVER_CONTINUE) << i;
  }
  EXPECT_EQ(improving.stalled(), nullptr);

  StallStop edge;  // a crawl that gains just more than the crawl rule's share goes on
  cost = 1.0;
  const double per_step = 1.5 * kCrawl.relative / kCrawl.window;
  for (int i = 1; i < 50; ++i) {
    cost *= 1 - per_step;
    ASSERT_EQ(edge(step(i, cost)), ceres::SOLVER_CONTINUE) << i;
  }
}

// Freudenstein and Roth's function (Moré, Garbow & Hillstrom 1981, problem 2) as an objective,
// r = (−13 + x + ((5 − y) y − 2) y, −29 + x + ((y + 1) y − 14) y), recording the cost at every
// point where derivatives were asked for, and every point evaluated.
class FreudensteinRothObjective final : public Objective {
 public:
  std::vector<double> derivative_costs;
  std::vector<Eigen::Vector2d> points;
  void reset(bool) override {}
  bool evaluate(const double* p, bool derivatives, ObjectiveValue& out, ParamValues&) override {
    const double x = p[0], y = p[1];
    points.emplace_back(x, y);
    const Eigen::Vector2d r(-13 + x + ((5 - y) * y - 2) * y, -29 + x + ((y + 1) * y - 14) * y);
    out.cost = r.squaredNorm();
    if (derivatives) {
      Eigen::Matrix2d j;
      j << 1, -3 * y * y + 10 * y - 2, 1, 3 * y * y + 2 * y - 14;
      out.gradient = j.transpose() * r;
      out.jtj = j.transpose() * j;
      derivative_costs.push_back(out.cost);
    }
    return true;
  }
};

// A level computes derivatives (on a fit's domain: one sweep per variable) at its start and where a
// step was accepted, never at the trial points of the bounded problem's line search: at most one
// per iteration, at strictly falling costs. (With Ceres' default cubic interpolation, this start
// takes 23 iterations and derivatives at 51 points, 22 of them above the cost before.)
TEST(SolveLevel, DerivativesOnlyWhereAStepWasAccepted) {
  const ParamTable table = {{"x", -20.0, 20.0, 0.5, Scope::Shared, false, "x"},
                            {"y", -20.0, 20.0, -2.0, Scope::Shared, false, "y"}};
  const SolverVariables vars(table, {false, false});
  auto inner = std::make_unique<FreudensteinRothObjective>();
  const FreudensteinRothObjective& counted = *inner;
  CachedObjective objective(std::move(inner), vars.size());
  std::vector<double> x = {0.5, -2.0};
  const LevelOutcome out = solve_level(objective, vars, x, FitSettings{}, true);
  ASSERT_TRUE(out.usable);
  const std::vector<double>& c = counted.derivative_costs;
  std::printf("%d iterations, derivatives at %zu points, x = (%g, %g)\n", out.iterations, c.size(), x[0], x[1]);
  ASSERT_GE(c.size(), 2u);
  EXPECT_LE(c.size(), size_t(out.iterations) + 1);
  for (size_t k = 1; k < c.size(); ++k) EXPECT_LT(c[k], c[k - 1]) << "derivatives at evaluation " << k;
}

// A level refining the previous level's optimum starts from the trust region's radius that level
// ended with: from a radius of 1e-3 (Levenberg-Marquardt's damping 1/radius = 1000) its first
// trial step is short, where Ceres' default radius (1e4) takes nearly the Gauss-Newton step of
// ~10. Both end in the same minimum (costs within 1e-6).
TEST(SolveLevel, RefiningLevelStartsFromThePreviousLevelsRadius) {
  const ParamTable table = {{"x", -20.0, 20.0, 0.5, Scope::Shared, false, "x"},
                            {"y", -20.0, 20.0, -2.0, Scope::Shared, false, "y"}};
  const SolverVariables vars(table, {false, false});
  const Eigen::Vector2d start(0.5, -2.0);
  auto run = [&](const LevelOutcome* previous, Eigen::Vector2d& first_trial, double& end_cost) {
    auto inner = std::make_unique<FreudensteinRothObjective>();
    const FreudensteinRothObjective& counted = *inner;
    CachedObjective objective(std::move(inner), vars.size());
    std::vector<double> x = {start.x(), start.y()};
    const LevelOutcome out = solve_level(objective, vars, x, FitSettings{}, true, previous);
    EXPECT_GE(counted.points.size(), 2u);
    first_trial = counted.points.at(1);
    end_cost = counted.derivative_costs.back();
    std::printf("%s: first trial step %.3g, %d iterations, end (%.9g, %.9g) at cost %.12g, radius %.3g\n",
                previous ? "refining" : "first", (first_trial - start).lpNorm<Eigen::Infinity>(), out.iterations,
                x[0], x[1], end_cost, out.radius);
    return out;
  };
  Eigen::Vector2d trial, trial_refining;
  double end = 0, end_refining = 0;
  const LevelOutcome first = run(nullptr, trial, end);
  ASSERT_TRUE(first.usable);
  EXPECT_GT(first.radius, 0.0);
  EXPECT_GT((trial - start).lpNorm<Eigen::Infinity>(), 5.0);
  LevelOutcome previous;
  previous.radius = 1e-3;
  ASSERT_TRUE(run(&previous, trial_refining, end_refining).usable);
  EXPECT_LT((trial_refining - start).lpNorm<Eigen::Infinity>(), 0.05);
  EXPECT_NEAR(end_refining, end, 1e-6 * end);
}

}  // namespace
}  // namespace brdfkit::fit
