#include "brdfkit/models/he_series_table.h"

#include <cmath>

#include "brdfkit/models/he_series.h"

namespace brdfkit {

// Written by the build (cmake/generators/he_series_table.cpp): HeSeriesTable::compute_nodes().
extern const int kHeSeriesTableColumns, kHeSeriesTableRows;
extern const double kHeSeriesTableNodes[];

const HeSeriesTable& HeSeriesTable::get() {
  static const HeSeriesTable table;
  return table;
}

HeSeriesTable::HeSeriesTable()
    : x0_(first_x()), nx_(kHeSeriesTableColumns), ny_(kHeSeriesTableRows), r_(kHeSeriesTableNodes) {}

double HeSeriesTable::operator()(double g, double c) const {
  if (!covers(g, c)) return he_series(g, c, kSummedTolerance);
  const double y = c / g;
  const double r = interpolate(r_, nx_, ny_, (std::log(g) - x0_) * kPerStepX, std::log1p(y) * kPerStepY);
  return std::exp(r - y) / g;
}

void HeSeriesTable::block(const double* g, const double* c, double* s) const {
  interpolate_block(g, c, s);
  for (std::size_t k = 0; k < kBlock; ++k)
    if (!covers(g[k], c[k])) s[k] = he_series(g[k], c[k], kSummedTolerance);
}

}  // namespace brdfkit
