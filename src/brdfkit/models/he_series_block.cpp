// HeSeriesTable's block look-up (he_series_table.h) as vector kernels: the expression of
// HeSeriesTable::operator() lane by lane, with glibc's vector log, log1p and exp, split at its
// two coordinates so that look-ups at one c/g share the y side.
#include "brdfkit/core/vector_kernel.h"
#include "brdfkit/models/he_series_table.h"

namespace brdfkit {

BRDFKIT_VECTOR_KERNEL void HeSeriesTable::rows(const double* __restrict ratio, Rows& __restrict out) const {
  const int ny = ny_;
  for (std::size_t k = 0; k < kBlock; ++k) {
    // Into the domain (a NaN to its edge): every lane computes, block_at replaces those outside.
    const double low = ratio[k] > 0 ? ratio[k] : 0;
    const double y = low < kYMax ? low : kYMax;
    const double fy = log1p(y) * kPerStepY;
    const int j = std::min(std::max(int(fy), 1), ny - 3);
    double w[4];
    lagrange4(fy - j, w);
    out.ratio[k] = ratio[k];
    out.y[k] = y;
    out.j[k] = j;
    for (int b = 0; b < 4; ++b) out.w[b][k] = w[b];
  }
}

BRDFKIT_VECTOR_KERNEL void HeSeriesTable::interpolate_block(const Rows& __restrict rows, const double* __restrict g,
                                                           double* __restrict s) const {
  // Locals: the stores to s must not make the compiler reload the table's members.
  const double* __restrict nodes = r_;
  const double x0 = x0_;
  const int nx = nx_, ny = ny_;
  for (std::size_t k = 0; k < kBlock; ++k) {
    const double g_low = g[k] > kGMin ? g[k] : kGMin;
    const double gk = g_low < kGMax ? g_low : kGMax;
    const double fx = (log(gk) - x0) * kPerStepX;
    const int i = std::min(std::max(int(fx), 1), nx - 3);
    double wx[4];
    lagrange4(fx - i, wx);
    // interpolate()'s sum, its row weights from `rows`.
    const double* column = nodes + std::size_t(i - 1) * std::size_t(ny) + std::size_t(rows.j[k] - 1);
    double r = 0;
    for (int b = 0; b < 4; ++b) {
      double row = 0;
      for (int a = 0; a < 4; ++a) row += wx[a] * column[std::size_t(a) * std::size_t(ny) + std::size_t(b)];
      r += rows.w[b][k] * row;
    }
    s[k] = exp(r - rows.y[k]) / gk;
  }
}

}  // namespace brdfkit
