#include <algorithm>
#include <cmath>

#include "brdfkit/core/vector_kernel.h"
#include "brdfkit/ndf/d_block.h"
#include "brdfkit/shadowing/smith_g1_row.h"

namespace brdfkit {

BRDFKIT_VECTOR_KERNEL void SmithG1Row::g1_lanes(const double* __restrict cos_theta, double* __restrict out) const {
  // Locals: the stores to out must not make the compiler reload the row's members.
  const double t_edge = t_edge_, scale = scale_;
  const double* __restrict g = g_.data();
  for (std::size_t k = 0; k < kDBlock; ++k) {
    const double c = cos_theta[k], s = std::sqrt(std::max(0.0, 1 - c * c));
    const double num = s - t_edge * c;
    // Every lane interpolates; those g1 answers without the row (c ≤ 0, or inside the support
    // edge) at node 0, and take their answer below.
    const double x = (c > 0 ? (num > 0 ? num / (num + scale * c) : 0.0) : 0.0) * kNodes;
    const int i = std::min(int(x), kNodes - 1);
    const double f = x - i, f2 = f * f, f3 = f2 * f;
    const double v = 0.5 * ((-f3 + 2 * f2 - f) * g[i] + (3 * f3 - 5 * f2 + 2) * g[i + 1] +
                            (-3 * f3 + 4 * f2 + f) * g[i + 2] + (f3 - f2) * g[i + 3]);
    out[k] = c > 0 ? (num > 0 ? v : 1.0) : 0.0;
  }
}

void SmithG1Row::g1_block(const double* cos_theta, double* out) const {
  // A grid chunk's block holds a few runs, a block of MERL cells one per pair: one run in eight
  // pairs separates the two.
  std::size_t runs = 1;
  for (std::size_t k = 1; k < kDBlock; ++k) runs += !(cos_theta[k] == cos_theta[k - 1]);
  if (runs * 8 > kDBlock) return g1_lanes(cos_theta, out);
  for (std::size_t k = 0; k < kDBlock; ++k)
    out[k] = k > 0 && cos_theta[k] == cos_theta[k - 1] ? out[k - 1] : g1(cos_theta[k]);
}

}  // namespace brdfkit
