#pragma once
// Σ w² x y over a block of samples: the inner products of variable projection's Gram matrices
// (projected_objective.h), for several (x, y) pairs in one sweep.
#include <cstddef>
#include <span>

namespace brdfkit::fit {

struct DotTerm {
  const double* x;
  const double* y;
};

// out[t] = Σ_{k<n} w2[k] x_t[k] y_t[k] for every term t. Each sum runs in four interleaved partial
// sums added in a fixed order: one running sum waits for each addition to finish, four keep the
// adder busy, and the order is the same on every machine. Terms are swept four at a time: their
// sums are independent chains the core runs side by side, and w² is read once for the four. Each
// out[t] equals weighted_dot(n, w2, x_t, y_t) to the bit.
void weighted_dots(std::size_t n, const double* w2, std::span<const DotTerm> terms, double* out);

double weighted_dot(std::size_t n, const double* w2, const double* x, const double* y);

}  // namespace brdfkit::fit
