#pragma once
// The Λ integrand of shadowing/smith_integral.h on blocks of points, for the distributions with a
// vector P22 (`void P22_block(const double* x, double* out) const` on kP22Block slopes, ndf/
// d_block.h): a lazily built Smith table node is ~10⁵ integrand values, and libm's scalar pow,
// exp and atan per value were most of a node's cost. The factors around P22 are vector arithmetic
// too (core/vector_kernel.h); Λ agrees with the point-by-point integral to 1e-12 relative
// (tests/shadowing/test_smith.cpp).
#include <algorithm>
#include <vector>

#include "brdfkit/ndf/d_block.h"

namespace brdfkit::smith_detail {

// At kP22Block points w = log s, with inv_t2 = 1/tan²θ: the slope x = (1 + s²)/tan²θ and the
// rest of the integrand, s² (s − atan s).
void integrand_factors_block(double inv_t2, const double* w, double* x, double* factor);

template <class Ndf>
concept HasP22Block = requires(const Ndf& ndf, const double* x, double* out) { ndf.P22_block(x, out); };

// out[k] = P22(x) s² (s − atan s) at w[k], for every point of w; the last block is padded with w = 0.
template <HasP22Block Ndf>
void integrand_batch(const Ndf& ndf, double inv_t2, const std::vector<double>& w, std::vector<double>& out) {
  out.resize(w.size());
  double wb[kP22Block], x[kP22Block], factor[kP22Block], p22[kP22Block];
  for (size_t b = 0; b < w.size(); b += kP22Block) {
    const size_t n = std::min(kP22Block, w.size() - b);
    std::fill(std::copy_n(w.data() + b, n, wb), wb + kP22Block, 0.0);
    integrand_factors_block(inv_t2, wb, x, factor);
    ndf.P22_block(x, p22);
    for (size_t k = 0; k < n; ++k) out[b + k] = p22[k] * factor[k];
  }
}

}  // namespace brdfkit::smith_detail
