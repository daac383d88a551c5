// What steers the solver between starts and levels: the subsampling strides (fit/sample_stride.h)
// and the stall stop (fit/stall_stop.h).
#include <gtest/gtest.h>

#include <numeric>
#include <set>

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

}  // namespace
}  // namespace brdfkit::fit
