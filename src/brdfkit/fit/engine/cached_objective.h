#pragma once
// An objective with what the solver asks twice answered from memory, and the lowest-cost point
// evaluated kept. On a bounded problem Ceres' projected line search asks for a trial point's cost
// (ceres_adapter.cpp), then the trust-region step asks for it again: the last successful result
// answers the repeat (the same numbers: evaluations are deterministic). A coarse level of
// the fit hands its lowest-cost point to the next (Ceres evaluates a step before its parameter
// tolerance discards it).
#include <limits>
#include <memory>
#include <vector>

#include "brdfkit/fit/engine/objective.h"

namespace brdfkit::fit {

class CachedObjective final : public Objective {
 public:
  explicit CachedObjective(std::unique_ptr<Objective> inner, std::size_t variables)
      : inner_(std::move(inner)), n_(variables) {}

  void reset(bool new_blocks) override {
    inner_->reset(new_blocks);
    last_.valid = false;
    best_ = {};
  }
  // Also false when the cost or its derivatives are not finite.
  bool evaluate(const double* x, bool derivatives, ObjectiveValue& out, ParamValues& values) override;
  void start_colours(ParamValues& pv) override { inner_->start_colours(pv); }

  // The point of lowest cost evaluated since the last reset (empty: none).
  const std::vector<double>& best_point() const { return best_.x; }

 private:
  std::unique_ptr<Objective> inner_;
  std::size_t n_;
  struct {
    bool valid = false;
    bool derivatives = false;
    std::vector<double> x;
    ObjectiveValue value;
    ParamValues values;
  } last_;
  struct {
    double cost = std::numeric_limits<double>::infinity();
    std::vector<double> x;
  } best_;
};

}  // namespace brdfkit::fit
