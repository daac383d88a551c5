#pragma once
// Ends a Ceres solve whose cost has stalled: the last kWindow successful steps together lowered it
// by less than kRelative of its value. In a degenerate valley (He's per-channel complex index
// trades with σ0/τ) Levenberg-Marquardt crawls for hundreds of steps at 1e-6 each, and on a full
// RGL grid every step costs 10–30 s; the metric (√cost) then moves by < 5e-5 relative per window.
// Well-posed fits reach Ceres' own tolerances first: on exact data the cost keeps falling by
// orders of magnitude until round-off, where the parameters are already converged.
#include <ceres/iteration_callback.h>

#include <vector>

namespace brdfkit::fit {

class StallStop final : public ceres::IterationCallback {
 public:
  static constexpr int kWindow = 5;
  static constexpr double kRelative = 1e-4;

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (s.iteration == 0 || !s.step_is_successful) return ceres::SOLVER_CONTINUE;
    costs_.push_back(s.cost);
    const size_t n = costs_.size();
    if (n > size_t(kWindow) && costs_[n - 1 - kWindow] - s.cost < kRelative * s.cost) {
      stalled_ = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    return ceres::SOLVER_CONTINUE;
  }
  bool stalled() const { return stalled_; }

 private:
  std::vector<double> costs_;
  bool stalled_ = false;
};

}  // namespace brdfkit::fit
