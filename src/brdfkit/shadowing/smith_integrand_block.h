#pragma once
// The Λ integrand of shadowing/smith_integral.h on blocks of points, for the distributions with a
// vector P22 (`void P22_block(const double* x, double* out) const` on kP22Block slopes, ndf/
// d_block.h): a lazily built Smith table node is ~10⁵ integrand values, and libm's scalar pow,
// exp and atan per value were most of a node's cost. The factors around P22 are vector arithmetic
// too (core/vector_kernel.h); Λ agrees with the point-by-point integral to 1e-12 relative
// (tests/shadowing/test_smith.cpp).
#include <cstddef>

#include "brdfkit/ndf/d_block.h"

namespace brdfkit::smith_detail {

// At the n points w[k] = log s, with inv_t2 = 1/tan²θ: the slope x = (1 + s²)/tan²θ and the rest
// of the integrand, s² (s − atan s); kP22Block points at a time, the last block padded.
void integrand_factors(double inv_t2, const double* w, std::size_t n, double* x, double* factor);

template <class Ndf>
concept HasP22Block = requires(const Ndf& ndf, const double* x, double* out) { ndf.P22_block(x, out); };

}  // namespace brdfkit::smith_detail
