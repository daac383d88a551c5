// HeSeriesTable::block's interpolation (he_series_table.h) as a vector kernel: the expression of
// HeSeriesTable::operator() lane by lane, with glibc's vector log, log1p and exp.
#include "brdfkit/core/vector_kernel.h"
#include "brdfkit/models/he_series_table.h"

namespace brdfkit {

BRDFKIT_VECTOR_KERNEL void HeSeriesTable::interpolate_block(const double* __restrict g, const double* __restrict c,
                                                           double* __restrict s) const {
  // Locals: the stores to s must not make the compiler reload the table's members.
  const double* __restrict nodes = r_;
  const double x0 = x0_;
  const int nx = nx_, ny = ny_;
  for (std::size_t k = 0; k < kBlock; ++k) {
    // Into the domain (a NaN to its edge): every lane computes, block() replaces those outside.
    const double g_low = g[k] > kGMin ? g[k] : kGMin;
    const double gk = g_low < kGMax ? g_low : kGMax;
    const double c_low = c[k] > 0 ? c[k] : 0;
    const double ck = c_low < kYMax * gk ? c_low : kYMax * gk;
    const double y = ck / gk;
    const double r = interpolate(nodes, nx, ny, (log(gk) - x0) * kPerStepX, log1p(y) * kPerStepY);
    s[k] = exp(r - y) / gk;
  }
}

}  // namespace brdfkit
