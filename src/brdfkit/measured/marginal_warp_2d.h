#pragma once
// Piecewise-bilinear 2D distribution on the unit square, conditioned on up to two parameters
// interpolated linearly between their nodes, with continuous sampling and its exact inverse.
// This is the data structure of Dupuy & Jakob 2018 §5 (their VNDF warp and the interpolation of
// the ndf/sigma/rgb tables), as in Mitsuba 3's Marginal2D<…, Continuous = true> and pbrt-v4's
// PiecewiseLinear2D: marginal CDF over rows (y), conditional CDF over columns (x), both of the
// bilinear interpolant (linear within a patch, so they invert by a quadratic).
#include <array>
#include <cstddef>
#include <vector>

#include "brdfkit/core/vec.h"

namespace brdfkit {

class MarginalWarp2D {
 public:
  MarginalWarp2D() = default;
  // `data`: slices × ny × nx values (x contiguous), slices = Π param node counts, the last
  // parameter varying fastest. `params`: the node values of each parameter (ascending, 0–2 of
  // them). With `distribution` false only eval() is available and it returns the raw bilinear
  // interpolant; with true the data are normalized to a density on [0,1]² and the CDFs built.
  MarginalWarp2D(const float* data, int nx, int ny, std::vector<std::vector<float>> params, bool distribution);

  // The slices a parameter value interpolates and their weights. Callers that evaluate many
  // points at one parameter value (all samples of one θi) compute them once and pass them to the
  // overloads below, which give the same values as the ones taking `param`.
  struct Weights {
    std::array<size_t, 4> slice{};  // up to 2 params → up to 4 slices
    std::array<double, 4> w{};
    int count = 1;
  };
  Weights weights(const double* param) const;

  // Where a point falls in the grid: its patch and the fractions within it. Tables of the same
  // resolution share it (RGL's three colour tables).
  struct Patch {
    size_t index;  // the patch's lower-left node
    double fx, fy;
  };
  Patch locate(const Vec2d& pos) const;

  // Bilinear interpolation at pos ∈ [0,1]² (clamped), parameters interpolated linearly.
  double eval(const Vec2d& pos, const double* param = nullptr) const { return eval(locate(pos), weights(param)); }
  double eval(const Vec2d& pos, const Weights& w) const { return eval(locate(pos), w); }
  double eval(const Patch& p, const Weights& w) const;
  // Unit square → distributed point, with its density (only if built as a distribution).
  std::pair<Vec2d, double> sample(Vec2d u, const double* param = nullptr) const;
  // Exact inverse of sample(): point → unit square, with the density at the point.
  std::pair<Vec2d, double> invert(Vec2d p, const double* param = nullptr) const { return invert(p, weights(param)); }
  std::pair<Vec2d, double> invert(Vec2d p, const Weights& w) const;

  int nx() const { return nx_; }
  int ny() const { return ny_; }

 private:
  double lookup(const std::vector<double>& table, size_t stride, const Weights& w, size_t index) const;

  int nx_ = 0, ny_ = 0;
  std::vector<std::vector<float>> params_;
  std::vector<size_t> param_stride_;
  std::vector<double> data_, marginal_cdf_, conditional_cdf_;
};

}  // namespace brdfkit
