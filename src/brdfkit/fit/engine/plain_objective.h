#pragma once
// The objective with every parameter a solver variable (a model without colours to project, such
// as Ashikhmin-Shirley whose colour is its Schlick F0): the metric's residual (residual.h) at every
// sample and its forward-difference Jacobian, reduced per block to JᵀJ and Jᵀr.
#include "brdfkit/fit/engine/objective.h"

namespace brdfkit::fit {

class PlainObjective final : public Objective {
 public:
  explicit PlainObjective(const FitContext& ctx) : ctx_(ctx) {}
  void reset(bool) override {}
  bool evaluate(const double* x, bool derivatives, ObjectiveValue& out, ParamValues& values) override;

 private:
  void block_partials(std::size_t i, const ParamValues& pv, const std::vector<ParamValues>& shifted,
                      const std::vector<double>& h, bool derivatives, double* acc) const;
  const FitContext& ctx_;
};

}  // namespace brdfkit::fit
