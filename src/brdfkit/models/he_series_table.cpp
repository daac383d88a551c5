#include "brdfkit/models/he_series_table.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>

#include "brdfkit/models/he_series.h"

namespace brdfkit {

namespace {

constexpr double kNodeTolerance = 1e-10;

}  // namespace

const HeSeriesTable& HeSeriesTable::get() {
  static const HeSeriesTable table;
  return table;
}

// One column below g = kGMin and two nodes beyond the top of each axis, so that a look-up inside the
// domain has its 4 × 4 nodes; at y = 0 (the first row) a look-up in the first cell takes the cubic
// through the rows 0 … 3.
HeSeriesTable::HeSeriesTable()
    : x0_(std::log(kGMin) - kStepX),
      nx_(int(std::ceil((std::log(kGMax) - x0_) / kStepX)) + 3),
      ny_(int(std::ceil(std::log1p(kYMax) / kStepY)) + 3) {
  r_.resize(size_t(nx_) * size_t(ny_));
  // Isolated: the first look-up may come from inside a parallel loop, and this thread must not
  // take one of that loop's tasks (which would wait on this very initialization).
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(0, nx_, [&](int i) {
      const double g = std::exp(x0_ + i * kStepX);
      for (int j = 0; j < ny_; ++j) {
        const double y = std::expm1(j * kStepY);
        r_[size_t(i) * size_t(ny_) + size_t(j)] = he_log_series(g, g * y, kNodeTolerance) + std::log(g) + y;
      }
    });
  });
}

bool HeSeriesTable::covers(double g, double c) const { return g >= kGMin && g <= kGMax && c >= 0 && c <= kYMax * g; }

double HeSeriesTable::operator()(double g, double c) const {
  if (!covers(g, c)) return he_series(g, c, kSummedTolerance);
  const double y = c / g;
  const double r = interpolate(r_.data(), nx_, ny_, (std::log(g) - x0_) * kPerStepX, std::log1p(y) * kPerStepY);
  return std::exp(r - y) / g;
}

void HeSeriesTable::block(const double* g, const double* c, double* s) const {
  interpolate_block(g, c, s);
  for (std::size_t k = 0; k < kBlock; ++k)
    if (!covers(g[k], c[k])) s[k] = he_series(g[k], c[k], kSummedTolerance);
}

}  // namespace brdfkit
