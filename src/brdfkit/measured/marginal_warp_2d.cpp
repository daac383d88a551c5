#include "brdfkit/measured/marginal_warp_2d.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace brdfkit {

namespace {

double safe_sqrt(double x) { return std::sqrt(std::max(0.0, x)); }

// Largest i in [0, n−2] with pred(i) true (pred monotone: true then false), 0 if none.
template <class Pred> int find_interval(int n, Pred pred) {
  int lo = 0, hi = n - 2;
  while (lo < hi) {
    const int mid = (lo + hi + 1) / 2;
    if (pred(mid)) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}

}  // namespace

MarginalWarp2D::MarginalWarp2D(const float* data, int nx, int ny, std::vector<std::vector<float>> params,
                               bool distribution)
    : nx_(nx), ny_(ny), params_(std::move(params)) {
  if (nx < 2 || ny < 2) throw std::invalid_argument("MarginalWarp2D: resolution must be at least 2 x 2");
  if (params_.size() > 2) throw std::invalid_argument("MarginalWarp2D: at most two parameters");
  // Strides in slices, the last parameter varying fastest; a single-node parameter has stride 0.
  size_t slices = 1;
  param_stride_.assign(params_.size(), 0);
  for (int i = int(params_.size()) - 1; i >= 0; --i) {
    const size_t res = params_[size_t(i)].size();
    if (res < 1) throw std::invalid_argument("MarginalWarp2D: empty parameter");
    param_stride_[size_t(i)] = res > 1 ? slices : 0;
    slices *= res;
  }
  const size_t n = size_t(nx) * size_t(ny);
  data_.assign(data, data + slices * n);
  if (!distribution) return;

  // Dupuy & Jakob 2018 §5: CDFs of the bilinear interpolant, integrated with the trapezoid rule
  // in units of patches (exact for a piecewise-linear function), then normalized per slice.
  conditional_cdf_.assign(slices * n, 0.0);
  marginal_cdf_.assign(slices * size_t(ny), 0.0);
  for (size_t s = 0; s < slices; ++s) {
    double* d = data_.data() + s * n;
    double* cond = conditional_cdf_.data() + s * n;
    double* marg = marginal_cdf_.data() + s * size_t(ny);
    for (int y = 0; y < ny; ++y) {
      double sum = 0;
      const size_t row = size_t(y) * size_t(nx);
      cond[row] = 0;
      for (int x = 0; x + 1 < nx; ++x) {
        sum += 0.5 * (d[row + size_t(x)] + d[row + size_t(x) + 1]);
        cond[row + size_t(x) + 1] = sum;
      }
    }
    double sum = 0;
    marg[0] = 0;
    for (int y = 0; y + 1 < ny; ++y) {
      sum += 0.5 * (cond[size_t(y + 1) * size_t(nx) - 1] + cond[size_t(y + 2) * size_t(nx) - 1]);
      marg[y + 1] = sum;
    }
    // An all-zero slice stays zero (its density is 0; sampling it is meaningless but finite).
    const double norm = sum > 0 ? 1.0 / sum : 0.0;
    for (size_t i = 0; i < n; ++i) {
      cond[i] *= norm;
      d[i] *= norm;
    }
    for (int y = 0; y < ny; ++y) marg[y] *= norm;
  }
}

MarginalWarp2D::Weights MarginalWarp2D::weights(const double* param) const {
  Weights r;
  r.slice[0] = 0;
  r.w[0] = 1;
  r.count = 1;
  for (size_t dim = 0; dim < params_.size(); ++dim) {
    const auto& nodes = params_[dim];
    if (nodes.size() == 1) continue;
    const double p = param[dim];
    const int i = find_interval(int(nodes.size()), [&](int k) { return nodes[size_t(k)] <= p; });
    const double p0 = nodes[size_t(i)], p1 = nodes[size_t(i) + 1];
    const double t = std::clamp((p - p0) / (p1 - p0), 0.0, 1.0);
    // Each existing slice splits into (index i, weight 1−t) and (index i+1, weight t).
    for (int k = r.count - 1; k >= 0; --k) {
      const size_t base = r.slice[size_t(k)] + param_stride_[dim] * size_t(i);
      const double w = r.w[size_t(k)];
      r.slice[size_t(2 * k)] = base;
      r.w[size_t(2 * k)] = w * (1 - t);
      r.slice[size_t(2 * k + 1)] = base + param_stride_[dim];
      r.w[size_t(2 * k + 1)] = w * t;
    }
    r.count *= 2;
  }
  return r;
}

double MarginalWarp2D::lookup(const std::vector<double>& table, size_t stride, const Weights& w, size_t index) const {
  double v = 0;
  for (int k = 0; k < w.count; ++k) v += w.w[size_t(k)] * table[w.slice[size_t(k)] * stride + index];
  return v;
}

MarginalWarp2D::Patch MarginalWarp2D::locate(const Vec2d& pos_in) const {
  const double px = std::clamp(pos_in.x(), 0.0, 1.0) * (nx_ - 1), py = std::clamp(pos_in.y(), 0.0, 1.0) * (ny_ - 1);
  const int ix = std::min(int(px), nx_ - 2), iy = std::min(int(py), ny_ - 2);
  return {size_t(iy) * size_t(nx_) + size_t(ix), px - ix, py - iy};
}

double MarginalWarp2D::eval(const Patch& p, const Weights& w) const {
  const size_t n = size_t(nx_) * size_t(ny_);
  const size_t i = p.index;
  const double fx = p.fx, fy = p.fy;
  const double v00 = lookup(data_, n, w, i), v10 = lookup(data_, n, w, i + 1);
  const double v01 = lookup(data_, n, w, i + size_t(nx_)), v11 = lookup(data_, n, w, i + size_t(nx_) + 1);
  const double v = (1 - fy) * ((1 - fx) * v00 + fx * v10) + fy * ((1 - fx) * v01 + fx * v11);
  return conditional_cdf_.empty() ? v : v * (nx_ - 1) * (ny_ - 1);
}

std::pair<Vec2d, double> MarginalWarp2D::sample(Vec2d u, const double* param) const {
  if (conditional_cdf_.empty()) throw std::logic_error("MarginalWarp2D::sample: not built as a distribution");
  const Weights w = weights(param);
  const size_t n = size_t(nx_) * size_t(ny_), nxs = size_t(nx_);
  constexpr double eps = 1e-12;
  u = u.cwiseMax(eps).cwiseMin(1 - eps);

  // Row: marginal CDF, then the quadratic of the linear row density within the row interval.
  auto marg = [&](int i) { return lookup(marginal_cdf_, size_t(ny_), w, size_t(i)); };
  const int row = find_interval(ny_, [&](int i) { return marg(i) < u.y(); });
  double sy = u.y() - marg(row);
  const size_t col_offset = size_t(row) * nxs;
  const double r0 = lookup(conditional_cdf_, n, w, col_offset + nxs - 1);
  const double r1 = lookup(conditional_cdf_, n, w, col_offset + 2 * nxs - 1);
  if (std::abs(r0 - r1) < 1e-4 * (r0 + r1)) sy = (r0 + r1) > 0 ? 2 * sy / (r0 + r1) : 0;
  else sy = (r0 - safe_sqrt(r0 * r0 - 2 * sy * (r0 - r1))) / (r0 - r1);

  // Column: conditional CDF at the fractional row, then the quadratic within the patch.
  double sx = u.x() * ((1 - sy) * r0 + sy * r1);
  auto cond = [&](int i) {
    return (1 - sy) * lookup(conditional_cdf_, n, w, col_offset + size_t(i)) +
           sy * lookup(conditional_cdf_, n, w, col_offset + nxs + size_t(i));
  };
  const int col = find_interval(nx_, [&](int i) { return cond(i) < sx; });
  sx -= cond(col);
  const size_t i = col_offset + size_t(col);
  const double v00 = lookup(data_, n, w, i), v10 = lookup(data_, n, w, i + 1);
  const double v01 = lookup(data_, n, w, i + nxs), v11 = lookup(data_, n, w, i + nxs + 1);
  const double c0 = (1 - sy) * v00 + sy * v01, c1 = (1 - sy) * v10 + sy * v11;
  if (std::abs(c0 - c1) < 1e-4 * (c0 + c1)) sx = (c0 + c1) != 0 ? 2 * sx / (c0 + c1) : 0;
  else sx = (c0 - safe_sqrt(c0 * c0 - 2 * sx * (c0 - c1))) / (c0 - c1);
  sx = std::clamp(sx, 0.0, 1.0);
  sy = std::clamp(sy, 0.0, 1.0);
  const Vec2d p((col + sx) / (nx_ - 1), (row + sy) / (ny_ - 1));
  return {p, ((1 - sx) * c0 + sx * c1) * (nx_ - 1) * (ny_ - 1)};
}

std::pair<Vec2d, double> MarginalWarp2D::invert(Vec2d p, const Weights& w) const {
  if (conditional_cdf_.empty()) throw std::logic_error("MarginalWarp2D::invert: not built as a distribution");
  const size_t n = size_t(nx_) * size_t(ny_), nxs = size_t(nx_);
  const double px = std::clamp(p.x(), 0.0, 1.0) * (nx_ - 1), py = std::clamp(p.y(), 0.0, 1.0) * (ny_ - 1);
  const int ix = std::min(int(px), nx_ - 2), iy = std::min(int(py), ny_ - 2);
  double sx = px - ix, sy = py - iy;
  const size_t i = size_t(iy) * nxs + size_t(ix);
  const double v00 = lookup(data_, n, w, i), v10 = lookup(data_, n, w, i + 1);
  const double v01 = lookup(data_, n, w, i + nxs), v11 = lookup(data_, n, w, i + nxs + 1);
  const double c0 = (1 - sy) * v00 + sy * v01, c1 = (1 - sy) * v10 + sy * v11;
  const double pdf = (1 - sx) * c0 + sx * c1;

  // x: CDF of the column position at the fractional row, over the row's total.
  sx *= c0 + 0.5 * sx * (c1 - c0);
  sx += (1 - sy) * lookup(conditional_cdf_, n, w, i) + sy * lookup(conditional_cdf_, n, w, i + nxs);
  const size_t row = size_t(iy) * nxs;
  const double r0 = lookup(conditional_cdf_, n, w, row + nxs - 1);
  const double r1 = lookup(conditional_cdf_, n, w, row + 2 * nxs - 1);
  const double total = (1 - sy) * r0 + sy * r1;
  sx = total > 0 ? sx / total : 0;
  // y: marginal CDF of the row position.
  sy *= r0 + 0.5 * sy * (r1 - r0);
  sy += lookup(marginal_cdf_, size_t(ny_), w, size_t(iy));
  return {Vec2d(std::clamp(sx, 0.0, 1.0), std::clamp(sy, 0.0, 1.0)), pdf * (nx_ - 1) * (ny_ - 1)};
}

}  // namespace brdfkit
