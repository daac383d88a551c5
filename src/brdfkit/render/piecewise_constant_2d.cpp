#include "brdfkit/render/piecewise_constant_2d.h"

#include <algorithm>

namespace brdfkit::render {
namespace {

// CDF of n cells into cdf[0..n] (normalized); returns the sum (0 leaves a uniform CDF).
double build_cdf(const double* w, int n, double* cdf) {
  cdf[0] = 0;
  for (int i = 0; i < n; ++i) cdf[i + 1] = cdf[i] + w[i];
  const double total = cdf[n];
  for (int i = 1; i <= n; ++i) cdf[i] = total > 0 ? cdf[i] / total : double(i) / n;
  return total;
}

// Inverts a CDF: the cell holding u and the position within it, in [0, 1).
double invert_cdf(const double* cdf, int n, double u, int* cell) {
  const int i = int(std::upper_bound(cdf, cdf + n + 1, u) - cdf) - 1;
  *cell = std::clamp(i, 0, n - 1);
  const double width = cdf[*cell + 1] - cdf[*cell];
  const double t = width > 0 ? (u - cdf[*cell]) / width : 0.5;
  return std::min((*cell + std::clamp(t, 0.0, 1.0)) / n, 1.0 - 1e-12);
}

}  // namespace

PiecewiseConstant2D::PiecewiseConstant2D(const std::vector<double>& weights, int nx, int ny)
    : nx_(nx), ny_(ny), weights_(weights), row_cdf_(size_t(ny) * size_t(nx + 1)), marginal_cdf_(size_t(ny) + 1) {
  std::vector<double> row_sum(size_t(ny), 0.0);
  for (int y = 0; y < ny; ++y)
    row_sum[size_t(y)] = build_cdf(&weights_[size_t(y) * size_t(nx)], nx, &row_cdf_[size_t(y) * size_t(nx + 1)]);
  integral_ = build_cdf(row_sum.data(), ny, marginal_cdf_.data()) / (double(nx) * ny);
}

Vec2d PiecewiseConstant2D::sample(const Vec2d& u, double* pdf) const {
  int row = 0, col = 0;
  const double y = invert_cdf(marginal_cdf_.data(), ny_, u.y(), &row);
  const double x = invert_cdf(&row_cdf_[size_t(row) * size_t(nx_ + 1)], nx_, u.x(), &col);
  *pdf = weights_[size_t(row) * size_t(nx_) + size_t(col)] / integral_;
  return Vec2d(x, y);
}

double PiecewiseConstant2D::pdf(const Vec2d& p) const {
  if (!valid()) return 0;
  const int col = std::clamp(int(p.x() * nx_), 0, nx_ - 1), row = std::clamp(int(p.y() * ny_), 0, ny_ - 1);
  return weights_[size_t(row) * size_t(nx_) + size_t(col)] / integral_;
}

}  // namespace brdfkit::render
