#pragma once
// Evaluation of a model over structure-of-arrays direction pairs (DESIGN.md §12): through the
// static type's own loop (no virtual call per sample, inlined, vectorizable) for the models the
// fitter knows by type, through Model::eval otherwise. Both give the same values.
#include <cstddef>

#include "brdfkit/models/model.h"

namespace brdfkit::fit {

struct SoaPairs {
  const double *wi_x, *wi_y, *wi_z, *wo_x, *wo_y, *wo_z;
};

using BatchEvalFn = void (*)(const double* p, int c, std::size_t n, const SoaPairs& d, double* out);

// The static loop for `model`, or nullptr when the fitter does not know its type.
BatchEvalFn batch_eval_for(const Model& model);

// out[k] = ρ_c(wi_k, wo_k) for k < n, with `fast` when given.
void eval_pairs(const Model& model, BatchEvalFn fast, const double* p, int c, std::size_t n, const SoaPairs& d,
                double* out);

}  // namespace brdfkit::fit
