// HeSeriesTable's block look-up (he_series_table.h) as vector kernels: the expression of
// HeSeriesTable::operator() lane by lane, with glibc's vector log, log1p and exp, split at its
// two coordinates so that look-ups at one c/g share the row side.
#include "brdfkit/core/vector_kernel.h"
#include "brdfkit/models/he_series_table.h"

namespace brdfkit {

BRDFKIT_VECTOR_KERNEL void HeSeriesTable::rows(const double* __restrict ratio, Rows& __restrict out) const {
  // Locals: the stores to out must not make the compiler reload the table's members.
  const double q0 = q0_;
  const int near_rows = ny_, far_rows = stride_ - ny_;
  for (std::size_t k = 0; k < kBlock; ++k) {
    // Every lane computes (row_at takes a ratio outside the domain at its edge), block_at replaces
    // those outside.
    const RowAt row = row_at(ratio[k], q0, near_rows, far_rows);
    double w[4];
    lagrange4(row.t, w);
    out.ratio[k] = ratio[k];
    out.y[k] = row.y;
    out.j[k] = row.j;
    for (int b = 0; b < 4; ++b) out.w[b][k] = w[b];
  }
}

BRDFKIT_VECTOR_KERNEL void HeSeriesTable::interpolate_block(const Rows& __restrict rows, const double* __restrict g,
                                                           double* __restrict s) const {
  // Locals: the stores to s must not make the compiler reload the table's members.
  const double* __restrict nodes = r_;
  const double x0 = x0_;
  const int nx = nx_, stride = stride_;
  for (std::size_t k = 0; k < kBlock; ++k) {
    const double g_low = g[k] > kGMin ? g[k] : kGMin;
    const double gk = g_low < kGMax ? g_low : kGMax;
    const double r = interpolate(nodes, nx, stride, (log(gk) - x0) * kPerStepX, rows.j[k], &rows.w[0][k], kBlock);
    s[k] = exp(r - rows.y[k]) / gk;
  }
}

BRDFKIT_VECTOR_KERNEL bool HeSeriesTable::lane_sources(const double* __restrict g, const double* __restrict c,
                                                       unsigned char* __restrict source) {
  unsigned char any = 0;
  for (std::size_t k = 0; k < kBlock; ++k) {
    const bool main = covers_main(g[k], c[k]), table = covers(g[k], c[k]);
    source[k] = main ? kMain : (table ? kLow : kSummed);
    any |= source[k];
  }
  return any != 0;
}

BRDFKIT_VECTOR_KERNEL void HeSeriesTable::low_block(const double* __restrict g, const double* __restrict c,
                                                   double* __restrict s) const {
  const double* __restrict nodes = low_;
  const double x0 = low_x0_;
  const int nx = low_nx_, ny = low_ny_;
  for (std::size_t k = 0; k < kLowLanes; ++k) s[k] = low_at(nodes, nx, ny, x0, g[k], c[k]);
}

}  // namespace brdfkit
