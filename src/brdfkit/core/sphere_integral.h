#pragma once
// Adaptive quadrature over rectangles of a 2-D parameter domain (nested Boost.Math
// Gauss–Kronrod), the integrator behind the albedo, normalization and χ² checks. Peaked
// integrands (sharp specular lobes) need breakpoints: integrate_grid sums the cells between
// caller-chosen breakpoints, each cell adaptively, so 15 nodes never straddle a whole lobe.
#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <vector>

namespace brdfkit {

// ∫_{x0}^{x1} ∫_{y0}^{y1} f(x, y) dy dx; rel_tol applies to each 1-D pass (inner 10× tighter).
template <class F>
double integrate_rect(const F& f, double x0, double x1, double y0, double y1, double rel_tol = 1e-8,
                      unsigned max_depth = 10) {
  using Gk = boost::math::quadrature::gauss_kronrod<double, 15>;
  auto inner = [&](double x) {
    return Gk::integrate([&](double y) { return f(x, y); }, y0, y1, max_depth, rel_tol * 0.1);
  };
  return Gk::integrate(inner, x0, x1, max_depth, rel_tol);
}

// Sum of integrate_rect over the cells between sorted breakpoints xs × ys.
template <class F>
double integrate_grid(const F& f, const std::vector<double>& xs, const std::vector<double>& ys,
                      double rel_tol = 1e-8, unsigned max_depth = 10) {
  double sum = 0;
  for (size_t i = 0; i + 1 < xs.size(); ++i)
    for (size_t j = 0; j + 1 < ys.size(); ++j)
      if (xs[i + 1] > xs[i] && ys[j + 1] > ys[j])
        sum += integrate_rect(f, xs[i], xs[i + 1], ys[j], ys[j + 1], rel_tol, max_depth);
  return sum;
}

// Sorted, de-duplicated breakpoints in [lo, hi]: n uniform cells plus, around each `focus`
// point, offsets ±first·ratio^k (k ≥ 0) while they stay inside — fine cells where a lobe peaks.
inline std::vector<double> breakpoints(double lo, double hi, int n, const std::vector<double>& focus = {},
                                       double first = 1e-3, double ratio = 4.0) {
  std::vector<double> b;
  for (int i = 0; i <= n; ++i) b.push_back(lo + (hi - lo) * i / n);
  for (double f : focus) {
    if (f >= lo && f <= hi) b.push_back(f);
    for (double d = first; d < hi - lo; d *= ratio) {
      if (f - d > lo) b.push_back(f - d);
      if (f + d < hi) b.push_back(f + d);
    }
  }
  std::sort(b.begin(), b.end());
  b.erase(std::unique(b.begin(), b.end()), b.end());
  return b;
}

}  // namespace brdfkit
