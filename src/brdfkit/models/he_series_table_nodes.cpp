// HeSeriesTable's nodes (he_series_table.h), summed from He et al. 1991 Eq. 78's series. The build
// runs this once (cmake/generators/he_series_table.cpp); the library keeps it for the test that
// compares the compiled-in nodes with it.
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cmath>

#include "brdfkit/models/he_series.h"
#include "brdfkit/models/he_series_table.h"

namespace brdfkit {

namespace {

constexpr double kNodeTolerance = 1e-10;

}  // namespace

// One column below g = kGMin, one far row below its domain and two nodes beyond the top of each
// axis, so that a look-up inside the domain has its 4 × 4 nodes; at y = 0 (the first row) a
// look-up in the first cell takes the cubic through the rows 0 … 3. The low run the same way from
// g = kGLow to kGMin, c to kRatioMax · kGMin.
HeSeriesTable::Nodes HeSeriesTable::compute_nodes() {
  const double x0 = first_x(), q0 = first_q();
  Nodes n{int(std::ceil((std::log(kGMax) - x0) / kStepX)) + 3, int(std::ceil(std::log1p(kYMax) / kStepY)) + 3,
          int(std::ceil((std::log(kRatioMax) - q0) / kStepQ)) + 3, {}};
  const std::size_t stride = std::size_t(n.rows + n.far_rows);
  n.r.resize(std::size_t(n.columns) * stride);
  // Isolated: a caller inside a parallel loop must not take one of that loop's tasks here.
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(0, n.columns, [&](int i) {
      const double g = std::exp(x0 + i * kStepX);
      double* column = n.r.data() + std::size_t(i) * stride;
      for (int j = 0; j < n.rows; ++j) {
        const double y = std::expm1(j * kStepY);
        column[j] = he_log_series(g, g * y, kNodeTolerance) + std::log(g) + y;
      }
      for (int j = 0; j < n.far_rows; ++j)
        column[n.rows + j] = he_log_series(g, g * std::exp(q0 + j * kStepQ), kNodeTolerance) + std::log(g);
    });
  });
  n.low_columns = int(std::ceil((std::log(kGMin) - first_low_x()) / kStepX)) + 3;
  n.low_rows = int(std::ceil(std::log1p(kRatioMax * kGMin) / kStepY)) + 3;
  n.low.resize(std::size_t(n.low_columns) * std::size_t(n.low_rows));
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(0, n.low_columns, [&](int i) {
      const double g = std::exp(first_low_x() + i * kStepX);
      double* column = n.low.data() + std::size_t(i) * std::size_t(n.low_rows);
      for (int j = 0; j < n.low_rows; ++j)
        column[j] = he_log_series(g, std::expm1(j * kStepY), kNodeTolerance) - std::log(g) + g;
    });
  });
  return n;
}

}  // namespace brdfkit
