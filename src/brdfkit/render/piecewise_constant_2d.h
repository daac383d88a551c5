#pragma once
// A piecewise-constant density on [0,1]² from a grid of non-negative weights, sampled by inverting
// a marginal CDF over rows and a conditional CDF within the chosen row (pbrt-v3 §13.6.7,
// Distribution2D; Mitsuba 3's Hierarchical2D is the same density). Environment-map sampling
// (pbrt-v3 §14.2.4) builds it from luminance × sin θ per pixel.
#include <vector>

#include "brdfkit/core/vec.h"

namespace brdfkit::render {

class PiecewiseConstant2D {
 public:
  PiecewiseConstant2D() = default;
  // `weights`: ny rows of nx values (x contiguous), all ≥ 0 and finite.
  PiecewiseConstant2D(const std::vector<double>& weights, int nx, int ny);

  // False when every weight is 0 (nothing to sample).
  bool valid() const { return integral_ > 0; }
  // u ∈ [0,1)² → point p ∈ [0,1)² with density pdf(p).
  Vec2d sample(const Vec2d& u, double* pdf) const;
  double pdf(const Vec2d& p) const;

 private:
  int nx_ = 0, ny_ = 0;
  double integral_ = 0;                      // mean weight
  std::vector<double> weights_;              // ny × nx
  std::vector<double> row_cdf_;              // ny × (nx + 1), each row's CDF normalized to 1
  std::vector<double> marginal_cdf_;         // ny + 1
};

}  // namespace brdfkit::render
