#include "brdfkit/models/he_series_table.h"

#include <algorithm>
#include <cmath>

#include "brdfkit/models/he_series.h"

namespace brdfkit {

// Written by the build (cmake/generators/he_series_table.cpp): HeSeriesTable::compute_nodes().
extern const int kHeSeriesTableColumns, kHeSeriesTableRows, kHeSeriesTableFarRows;
extern const double kHeSeriesTableNodes[];

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
      r_(kHeSeriesTableNodes) {}

double HeSeriesTable::operator()(double g, double c) const {
  if (!covers(g, c)) return he_series(g, c, kSummedTolerance);
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
  for (std::size_t k = 0; k < kBlock; ++k)
    if (!covers(g[k], c[k])) s[k] = he_series(g[k], c[k], kSummedTolerance);
}

void HeSeriesTable::block_at(const Rows& rows, const double* g, double* s) const {
  interpolate_block(rows, g, s);
  for (std::size_t k = 0; k < kBlock; ++k) {
    const double c = rows.ratio[k] * g[k];
    if (!covers(g[k], c)) s[k] = he_series(g[k], c, kSummedTolerance);
  }
}

}  // namespace brdfkit
