// ExponentialPowerG1Table::b_coordinate_block: the table coordinate with glibc's vector math
// (core/vector_kernel.h), for HolzschuchPacanowski's batch loop.
#include <cstddef>

#include "brdfkit/core/vector_kernel.h"
#include "brdfkit/ndf/d_block.h"
#include "brdfkit/shadowing/exponential_power_g1.h"

namespace brdfkit {
namespace {

BRDFKIT_VECTOR_KERNEL void b_coordinates(const double* __restrict z, double* __restrict b) {
  for (std::size_t k = 0; k < kDBlock; ++k)
    b[k] = exp(-pow(1.0 / z[k], 1.0 / 20)) * (ExponentialPowerG1Table::kNb - 1);  // seed 004 §5.5
}

}  // namespace

void ExponentialPowerG1Table::b_coordinate_block(const double* z, double* b) { b_coordinates(z, b); }

}  // namespace brdfkit
