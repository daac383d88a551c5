#include "brdfkit/shadowing/smith_integrand_block.h"

#include <algorithm>
#include <cstddef>

#include "brdfkit/core/vector_kernel.h"

namespace brdfkit::smith_detail {
namespace {

// smith_integral.h's integrand in w = log s without P22; s − atan s as its s_minus_atan (the
// series below s = 1e-2, where the difference cancels).
BRDFKIT_VECTOR_KERNEL void factors(double inv_t2, const double* __restrict w, double* __restrict x,
                                   double* __restrict factor) {
  for (std::size_t k = 0; k < kP22Block; ++k) {
    const double s = exp(w[k]), s2 = s * s;
    x[k] = (1.0 + s2) * inv_t2;
    const double series = s * s2 * (1.0 / 3 - s2 * (1.0 / 5 - s2 * (1.0 / 7 - s2 / 9)));
    factor[k] = s2 * (s < 1e-2 ? series : s - atan(s));
  }
}

}  // namespace

void integrand_factors(double inv_t2, const double* w, std::size_t n, double* x, double* factor) {
  double wb[kP22Block], xb[kP22Block], fb[kP22Block];
  for (std::size_t b = 0; b < n; b += kP22Block) {
    const std::size_t m = std::min(kP22Block, n - b);
    std::fill(std::copy_n(w + b, m, wb), wb + kP22Block, 0.0);
    factors(inv_t2, wb, xb, fb);
    std::copy_n(xb, m, x + b);
    std::copy_n(fb, m, factor + b);
  }
}

}  // namespace brdfkit::smith_detail
