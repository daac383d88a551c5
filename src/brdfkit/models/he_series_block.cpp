// HeSeriesTable::block's interpolation (he_series_table.h) as a vector kernel: the expression of
// HeSeriesTable::operator() lane by lane, with glibc's vector log, log1p and exp.
#include <algorithm>

#include "brdfkit/core/vector_kernel.h"
#include "brdfkit/models/he_series_table.h"

namespace brdfkit {

BRDFKIT_VECTOR_KERNEL void HeSeriesTable::interpolate_block(const double* __restrict g, const double* __restrict c,
                                                           double* __restrict s) const {
  // Locals: the stores to s must not make the compiler reload the table's members.
  const double* __restrict nodes = r_.data();
  const double x0 = x0_;
  const int nx = nx_, ny = ny_;
  for (std::size_t k = 0; k < kBlock; ++k) {
    // Into the domain (a NaN to its edge): every lane computes, block() replaces those outside.
    const double g_low = g[k] > kGMin ? g[k] : kGMin;
    const double gk = g_low < kGMax ? g_low : kGMax;
    const double c_low = c[k] > 0 ? c[k] : 0;
    const double ck = c_low < kYMax * gk ? c_low : kYMax * gk;
    const double fx = (log(gk) - x0) * kPerStepX;
    const int i = std::min(std::max(int(fx), 1), nx - 3);
    double wx[4];
    lagrange4(fx - i, wx);
    const double y = ck / gk;
    const double fy = log1p(y) * kPerStepY;
    const int j = std::min(std::max(int(fy), 1), ny - 3);
    double wy[4];
    lagrange4(fy - j, wy);
    double r = 0;
    for (int b = 0; b < 4; ++b) {
      double row = 0;
      for (int a = 0; a < 4; ++a) row += wx[a] * nodes[std::size_t(i - 1 + a) * std::size_t(ny) + std::size_t(j - 1 + b)];
      r += wy[b] * row;
    }
    s[k] = exp(r - y) / gk;
  }
}

}  // namespace brdfkit
