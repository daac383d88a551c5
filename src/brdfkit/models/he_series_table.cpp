#include "brdfkit/models/he_series_table.h"

#include <algorithm>
#include <cmath>

#include "brdfkit/models/he_series.h"

namespace brdfkit {

// Written by the build (cmake/generators/he_series_table.cpp): HeSeriesTable::compute_nodes().
extern const int kHeSeriesTableColumns, kHeSeriesTableRows, kHeSeriesTableFarRows, kHeSeriesTableLowColumns,
    kHeSeriesTableLowRows;
extern const double kHeSeriesTableNodes[], kHeSeriesTableLowNodes[];

const HeSeriesTable& HeSeriesTable::get() {
  static const HeSeriesTable table;
  return table;
}

HeSeriesTable::HeSeriesTable()
    : x0_(first_x()),
      q0_(first_q()),
      nx_(kHeSeriesTableColumns),
      ny_(kHeSeriesTableRows),
      stride_(kHeSeriesTableRows + kHeSeriesTableFarRows),
      r_(kHeSeriesTableNodes),
      low_x0_(first_low_x()),
      low_nx_(kHeSeriesTableLowColumns),
      low_ny_(kHeSeriesTableLowRows),
      low_(kHeSeriesTableLowNodes) {}

double HeSeriesTable::operator()(double g, double c) const {
  if (!covers(g, c)) return he_series(g, c, kSummedTolerance);
  if (!covers_main(g, c)) return low_at(low_, low_nx_, low_ny_, low_x0_, g, c);
  const RowAt row = row_at(c / g, q0_, ny_, stride_ - ny_);
  double wy[4];
  lagrange4(row.t, wy);
  const double r = interpolate(r_, nx_, stride_, (std::log(g) - x0_) * kPerStepX, row.j, wy, 1);
  return std::exp(r - row.y) / g;
}

void HeSeriesTable::block(const double* g, const double* c, double* s) const {
  double ratio[kBlock];  // operator()'s c/g where the table covers (g, c); other lanes are replaced below
  for (std::size_t k = 0; k < kBlock; ++k) ratio[k] = c[k] / std::clamp(g[k], kGMin, kGMax);
  Rows r;
  rows(ratio, r);
  interpolate_block(r, g, s);
  fill_uncovered(g, c, s);
}

void HeSeriesTable::block_at(const Rows& rows, const double* g, double* s) const {
  interpolate_block(rows, g, s);
  double c[kBlock];
  for (std::size_t k = 0; k < kBlock; ++k) c[k] = rows.ratio[k] * g[k];
  fill_uncovered(g, c, s);
}

void HeSeriesTable::fill_uncovered(const double* g, const double* c, double* s) const {
  // Most blocks lie in the near and far runs; near grazing directions a block mixes the runs.
  unsigned char source[kBlock];
  if (!lane_sources(g, c, source)) return;
  std::size_t low[kBlock], summed[kBlock], n_low = 0, n_summed = 0;
  for (std::size_t k = 0; k < kBlock; ++k) {  // the lanes of each, listed without branches
    low[n_low] = k;
    n_low += source[k] == kLow;
    summed[n_summed] = k;
    n_summed += source[k] == kSummed;
  }
  for (std::size_t i = 0; i < n_summed; ++i) s[summed[i]] = he_series(g[summed[i]], c[summed[i]], kSummedTolerance);
  if (n_low == 0) return;
  // The low run's lanes gathered, kLowLanes at a time (the last group padded with a point inside the run).
  double low_g[kBlock + kLowLanes], low_c[kBlock + kLowLanes], low_s[kBlock + kLowLanes];
  for (std::size_t i = 0; i < n_low; ++i) {
    low_g[i] = g[low[i]];
    low_c[i] = c[low[i]];
  }
  const std::size_t padded = (n_low + kLowLanes - 1) / kLowLanes * kLowLanes;
  std::fill(low_g + n_low, low_g + padded, kGMin / 2);
  std::fill(low_c + n_low, low_c + padded, 0.0);
  for (std::size_t first = 0; first < padded; first += kLowLanes) low_block(low_g + first, low_c + first, low_s + first);
  for (std::size_t i = 0; i < n_low; ++i) s[low[i]] = low_s[i];
}

}  // namespace brdfkit
