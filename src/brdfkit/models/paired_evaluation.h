#pragma once
// A capability some models offer besides the Model interface: ρ at two values of one parameter in
// one pass, when the other terms are costly and do not depend on it (Cook-Torrance's D and G under
// its Fresnel F0). Variable projection evaluates a Fresnel-paired colour's two linear bases this
// way (fit/engine/projected_objective.h); code that needs it asks a Model for it with dynamic_cast.
#include <cstddef>

#include "brdfkit/models/model.h"

namespace brdfkit {

class PairedEvaluation {
 public:
  virtual ~PairedEvaluation() = default;
  // Model::eval_batch with parameter `param` set to a (into out_a) and to b (into out_b), the
  // values of two eval_batch calls to the bit. False, with nothing written, where the model has
  // no shared work for that parameter.
  virtual bool eval_batch_pair(const double* p, int c, int param, double a, double b, std::size_t n,
                               const SoaPairs& d, double* out_a, double* out_b) const = 0;
};

}  // namespace brdfkit
