#include "brdfkit/models/he_series_table.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>

#include "brdfkit/models/he_series.h"

namespace brdfkit {

namespace {

constexpr double kGMin = 2, kGMax = 1e4, kYMax = 1000;  // c/g ≤ kYMax
constexpr double kStepX = 0.03, kStepY = 0.01;
constexpr double kNodeTolerance = 1e-10;
// One column below g = kGMin and two nodes beyond the top of each axis, so that a look-up inside the
// domain has its 4 × 4 nodes; at y = 0 (the first row) a look-up in the first cell takes the cubic
// through the rows 0 … 3.
const double kX0 = std::log(kGMin) - kStepX;

bool g_in_domain(double g) { return g >= kGMin && g <= kGMax; }
bool c_in_domain(double g, double c) { return c >= 0 && c <= kYMax * g; }

// Weights of the cubic Lagrange interpolant through the nodes at −1, 0, 1, 2, at t ∈ [0, 1].
void lagrange4(double t, double w[4]) {
  w[0] = -t * (t - 1) * (t - 2) / 6;
  w[1] = (t + 1) * (t - 1) * (t - 2) / 2;
  w[2] = -(t + 1) * t * (t - 2) / 2;
  w[3] = (t + 1) * t * (t - 1) / 6;
}

}  // namespace

const HeSeriesTable& HeSeriesTable::get() {
  static const HeSeriesTable table;
  return table;
}

HeSeriesTable::HeSeriesTable()
    : nx_(int(std::ceil((std::log(kGMax) - kX0) / kStepX)) + 3), ny_(int(std::ceil(std::log1p(kYMax) / kStepY)) + 3) {
  r_.resize(size_t(nx_) * size_t(ny_));
  // Isolated: the first look-up may come from inside a parallel loop, and this thread must not
  // take one of that loop's tasks (which would wait on this very initialization).
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(0, nx_, [&](int i) {
      const double g = std::exp(kX0 + i * kStepX);
      for (int j = 0; j < ny_; ++j) {
        const double y = std::expm1(j * kStepY);
        r_[size_t(i) * size_t(ny_) + size_t(j)] = he_log_series(g, g * y, kNodeTolerance) + std::log(g) + y;
      }
    });
  });
}

bool HeSeriesTable::covers(double g, double c) const { return g_in_domain(g) && c_in_domain(g, c); }

HeSeriesTable::Column HeSeriesTable::column(double g) const {
  Column col;
  col.g = g;
  col.in_range = g_in_domain(g);
  if (!col.in_range) return col;
  const double fx = (std::log(g) - kX0) / kStepX;
  col.i = std::clamp(int(fx), 1, nx_ - 3);
  lagrange4(fx - col.i, col.wx);
  return col;
}

double HeSeriesTable::operator()(const Column& col, double c) const {
  const double g = col.g;
  if (!(col.in_range && c_in_domain(g, c))) return he_series(g, c, kSummedTolerance);  // !covers(g, c)
  const double y = c / g;
  const double fy = std::log1p(y) / kStepY;
  const int j = std::clamp(int(fy), 1, ny_ - 3);
  double wy[4];
  lagrange4(fy - j, wy);
  double r = 0;
  for (int b = 0; b < 4; ++b) {
    double row = 0;
    for (int a = 0; a < 4; ++a) row += col.wx[a] * node(col.i - 1 + a, j - 1 + b);
    r += wy[b] * row;
  }
  return std::exp(r - y) / g;
}

}  // namespace brdfkit
