#pragma once
// Ends a Ceres solve whose cost has stalled, by either of two rules over its successful steps:
// - a crawl: the last 5 steps together lowered the cost by less than 1e-4 of it. In a degenerate
//   valley (He's per-channel complex index trades with σ0/τ) Levenberg-Marquardt crawls for
//   hundreds of steps at 1e-6 each, and on a full RGL grid every step costs seconds;
// - settled: the last 2 steps together lowered it by less than 1e-5 of it. Near the optimum of
//   any fit the last steps each gain < 1e-6 while costing a full sweep per variable; the metric
//   (√cost) would move by < 5e-6 relative per further step (bench/main_job.sh compares every
//   fit's error with the last full run's).
// Well-posed fits on exact data never stall: their cost keeps falling by orders of magnitude
// until Ceres' own tolerances end the solve. Only the end is moved, never a step: a solve stops
// at or before where the crawl rule alone would have stopped it, on the same path.
#include <ceres/iteration_callback.h>

#include <vector>

namespace brdfkit::fit {

struct StallRule {
  int window;
  double relative;
};
inline constexpr StallRule kCrawl{5, 1e-4};
inline constexpr StallRule kSettled{2, 1e-5};

class StallStop final : public ceres::IterationCallback {
 public:
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (s.iteration == 0 || !s.step_is_successful) return ceres::SOLVER_CONTINUE;
    costs_.push_back(s.cost);
    for (const StallRule* r : {&kCrawl, &kSettled})
      if (gained_less(*r)) {
        stalled_ = r;
        return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
      }
    return ceres::SOLVER_CONTINUE;
  }
  // The rule that ended the solve, or null.
  const StallRule* stalled() const { return stalled_; }

 private:
  bool gained_less(const StallRule& r) const {
    const size_t n = costs_.size(), w = size_t(r.window);
    return n > w && costs_[n - 1 - w] - costs_[n - 1] < r.relative * costs_[n - 1];
  }

  std::vector<double> costs_;
  const StallRule* stalled_ = nullptr;
};

}  // namespace brdfkit::fit
