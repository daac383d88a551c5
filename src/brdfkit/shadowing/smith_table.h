#pragma once
// Tabulated Smith Λ over (distribution parameters, tanθ), so that Λ inside a fit costs tens of ns
// instead of a quadrature (DESIGN.md §4: "tabulated … over a parameter grid, interpolated at run
// time"). Built once per distribution type from smith_lambda_integral (shadowing/smith_integral.h).
//
// Coordinates, chosen so that the interpolated function is smooth and nearly separable:
//  - each parameter on its own axis, logarithmic for scale-like parameters (α, σ) and linear for
//    shape parameters (p, γ);
//  - tanθ through v = log t − L(params), where L = log t½ and Λ(t½) = 1 (G1 = ½). For scale
//    families (Λ(t; α) = Λ₁(α t): Beckmann, GGX, exponential, exponential power at fixed p) the
//    table is then constant along the scale axis and L is linear in log α, so interpolation along
//    that axis is exact; for SGD (α, p) and GTR (α, γ) the shift still aligns the transitions.
//  - the tabulated value is log Λ: it is linear in v at both ends (log Λ ≈ v + const for t → ∞, and
//    2v + const for power-law tails at t → 0), where the table is extrapolated linearly, and
//    light tails (Beckmann) fall off so fast that G1 = 1 to double precision below the table.
// Interpolation is Catmull-Rom (cubic) along every axis, edges padded by linear extrapolation,
// so ceres::Jet parameters and tanθ carry continuous derivatives through the weights.
#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include "brdfkit/shadowing/smith_integral.h"

namespace brdfkit {

struct SmithAxis {
  double lo;
  double hi;
  int n;           // nodes, ≥ 2
  bool log_scale;  // interpolate in log(value)
};

class SmithLambdaTable {
 public:
  static constexpr int kMaxDims = 3;
  // Grid in v = log t − log t½ and its spacing (accuracy target ~1e-5 on G1, DESIGN.md §4).
  static constexpr double kVLo = -6.0, kVHi = 6.0, kVStep = 0.075;

  // lambda(params, t) must return Λ for the parameter values `params` (in axes order) and t = tanθ.
  SmithLambdaTable(std::vector<SmithAxis> axes, const std::function<double(const double*, double)>& lambda);

  int dims() const { return static_cast<int>(axes_.size()); }
  const std::vector<SmithAxis>& axes() const { return axes_; }
  // Whether the parameter values lie inside the tabulated box (outside, callers integrate directly).
  bool covers(const double* params) const;

  template <class T> T lambda(const T* params, const T& tan_theta) const;

 private:
  // Padded grids: one extra node on each side of every axis (linear extrapolation), so the four
  // Catmull-Rom neighbours of any cell exist.
  std::vector<SmithAxis> axes_;
  std::vector<int> pn_;         // padded node count per parameter axis
  int nv_ = 0;                  // padded v nodes
  std::vector<double> log_t_half_;  // over the parameter grid
  std::vector<double> log_lambda_;  // over the parameter grid × v, v fastest

  template <class T> static void catmull_rom(const T& f, T w[4]) {
    const T f2 = f * f, f3 = f2 * f;
    w[0] = T(0.5) * (-f3 + T(2) * f2 - f);
    w[1] = T(0.5) * (T(3) * f3 - T(5) * f2 + T(2));
    w[2] = T(0.5) * (T(-3) * f3 + T(4) * f2 + f);
    w[3] = T(0.5) * (f3 - f2);
  }
  // Cell index (first of the 4 padded neighbours) and fractional weights along an axis of `n`
  // real nodes, for the continuous real-node coordinate x (clamped to the grid).
  template <class T> static int cell(const T& x, int n, T w[4]) {
    int i = static_cast<int>(std::floor(smith_detail::scalar(x)));
    i = std::clamp(i, 0, n - 2);
    catmull_rom(T(x - T(i)), w);
    return i;  // padded neighbours i .. i+3 = real nodes i−1 .. i+2
  }
};

template <class T> T SmithLambdaTable::lambda(const T* params, const T& tan_theta) const {
  using std::exp;
  using std::log;
  if (!(smith_detail::scalar(tan_theta) > 0.0)) return T(0);
  const int d = dims();
  int base[kMaxDims] = {0, 0, 0};
  T w[kMaxDims][4];
  for (int k = 0; k < d; ++k) {
    const SmithAxis& a = axes_[k];
    const T u = a.log_scale ? T((log(params[k]) - std::log(a.lo)) / (std::log(a.hi) - std::log(a.lo)))
                            : T((params[k] - a.lo) / (a.hi - a.lo));
    base[k] = cell(T(u * double(a.n - 1)), a.n, w[k]);
  }
  // Σ over the 4^d parameter neighbours of weight × (grid value at offset `off` in the last axis).
  const int combos = 1 << (2 * d);
  auto blend = [&](const std::vector<double>& grid, int stride_last, auto&& inner) -> T {
    T sum(0);
    for (int c = 0; c < combos; ++c) {
      size_t idx = 0;
      T wt(1);
      for (int k = 0; k < d; ++k) {
        const int o = (c >> (2 * k)) & 3;
        idx = idx * pn_[k] + (base[k] + o);
        wt = wt * w[k][o];
      }
      sum += wt * inner(grid, idx * stride_last);
    }
    return sum;
  };
  const T log_t_half = blend(log_t_half_, 1, [](const std::vector<double>& g, size_t i) { return T(g[i]); });
  const T v = log(tan_theta) - log_t_half;
  const double real_nv = nv_ - 2;
  const T xv = (v - T(kVLo)) / T(kVStep);
  // log Λ at real v node j, interpolated over the parameters.
  auto at_node = [&](int j) {
    return blend(log_lambda_, nv_, [&](const std::vector<double>& g, size_t i) { return T(g[i + j + 1]); });
  };
  const double xs = smith_detail::scalar(xv);
  T log_lambda;
  if (xs < 0.0) {
    const T f0 = at_node(0), f1 = at_node(1);
    log_lambda = f0 + (f1 - f0) * xv;
  } else if (xs > real_nv - 1) {
    const int last = static_cast<int>(real_nv) - 1;
    const T f0 = at_node(last - 1), f1 = at_node(last);
    log_lambda = f1 + (f1 - f0) * (xv - T(double(last)));
  } else {
    T wv[4];
    const int iv = cell(xv, static_cast<int>(real_nv), wv);
    log_lambda = blend(log_lambda_, nv_, [&](const std::vector<double>& g, size_t i) {
      const double* p = &g[i + iv];
      return wv[0] * p[0] + wv[1] * p[1] + wv[2] * p[2] + wv[3] * p[3];
    });
  }
  return exp(log_lambda);
}

}  // namespace brdfkit
