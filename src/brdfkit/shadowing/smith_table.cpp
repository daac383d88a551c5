#include "brdfkit/shadowing/smith_table.h"

#include <boost/math/tools/roots.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace brdfkit {

namespace {

// log Λ, floored where Λ underflows: there G1 = 1 to double precision and the floor only has to
// keep the interpolant finite.
constexpr double kLogFloor = -700.0;
double safe_log(double x) { return x > 0.0 ? std::max(kLogFloor, std::log(x)) : kLogFloor; }

double axis_value(const SmithAxis& a, int i) {
  const double u = double(i) / double(a.n - 1);
  return a.log_scale ? std::exp(std::log(a.lo) + u * (std::log(a.hi) - std::log(a.lo))) : a.lo + u * (a.hi - a.lo);
}

// log t½ with Λ(t½) = 1: Λ grows monotonically with t (from 0 to ∞), so a bracket in log t
// expanded by factors of e² always closes; Boost's TOMS 748 then converges in ~10 evaluations.
double log_t_half(const std::function<double(double)>& lambda_of_t) {
  auto f = [&](double u) { return safe_log(lambda_of_t(std::exp(u))); };
  double lo = 0.0, hi = 0.0, flo = f(lo), fhi = flo;
  if (flo < 0.0) {
    while (fhi < 0.0) {
      lo = hi;
      flo = fhi;
      hi += 2.0;
      fhi = f(hi);
      if (hi > 80.0) throw std::runtime_error("smith table: Lambda never reaches 1");
    }
  } else {
    while (flo >= 0.0) {
      hi = lo;
      fhi = flo;
      lo -= 2.0;
      flo = f(lo);
      if (lo < -80.0) throw std::runtime_error("smith table: Lambda stays above 1");
    }
  }
  std::uintmax_t iters = 60;
  const auto r = boost::math::tools::toms748_solve(f, lo, hi, flo, fhi, boost::math::tools::eps_tolerance<double>(50), iters);
  return 0.5 * (r.first + r.second);
}

// Fills the padding of a row-major grid with dims `n` (padded sizes, real nodes 1..n−2) along
// axis `axis` by quadratic extrapolation from the three nearest real nodes, so that the edge
// cells interpolate as accurately as interior ones (Catmull-Rom reproduces quadratics; a linear
// ghost node made the edge cells 30× worse on SGD).
void pad_axis(std::vector<double>& g, const std::vector<int>& n, int axis) {
  size_t stride = 1;
  for (size_t k = axis + 1; k < n.size(); ++k) stride *= n[k];
  size_t outer = 1;
  for (int k = 0; k < axis; ++k) outer *= n[k];
  const size_t len = n[axis];
  for (size_t o = 0; o < outer; ++o)
    for (size_t s = 0; s < stride; ++s) {
      double* p = &g[o * len * stride + s];
      p[0] = 3 * p[stride] - 3 * p[2 * stride] + p[3 * stride];
      p[(len - 1) * stride] = 3 * p[(len - 2) * stride] - 3 * p[(len - 3) * stride] + p[(len - 4) * stride];
    }
}

}  // namespace

SmithLambdaTable::SmithLambdaTable(std::vector<SmithAxis> axes,
                                   const std::function<double(const double*, double)>& lambda)
    : axes_(std::move(axes)) {
  const int d = dims();
  if (d < 1 || d > kMaxDims) throw std::invalid_argument("SmithLambdaTable: 1 to 3 parameter axes");
  for (const auto& a : axes_)
    if (a.n < 3 || !(a.hi > a.lo) || (a.log_scale && !(a.lo > 0.0)))
      throw std::invalid_argument("SmithLambdaTable: bad axis");
  const int real_nv = static_cast<int>(std::lround((kVHi - kVLo) / kVStep)) + 1;
  nv_ = real_nv + 2;
  size_t n_param_nodes = 1, n_padded = 1;
  pn_.resize(d);
  for (int k = 0; k < d; ++k) {
    pn_[k] = axes_[k].n + 2;
    n_param_nodes *= axes_[k].n;
    n_padded *= pn_[k];
  }
  log_t_half_.assign(n_padded, 0.0);
  log_lambda_.assign(n_padded * nv_, 0.0);

  // The build runs inside a TBB arena isolation: a caller that is itself a TBB task (a parallel
  // fit) must not steal an outer task that waits on this table's lazy initialisation.
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n_param_nodes), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t node = r.begin(); node != r.end(); ++node) {
        double p[kMaxDims];
        size_t rem = node, padded = 0;
        int idx[kMaxDims];
        for (int k = d - 1; k >= 0; --k) {
          idx[k] = static_cast<int>(rem % axes_[k].n);
          rem /= axes_[k].n;
        }
        for (int k = 0; k < d; ++k) {
          p[k] = axis_value(axes_[k], idx[k]);
          padded = padded * pn_[k] + (idx[k] + 1);
        }
        auto lam = [&](double t) { return lambda(p, t); };
        const double lth = log_t_half(lam);
        log_t_half_[padded] = lth;
        double* row = &log_lambda_[padded * nv_];
        for (int j = 0; j < real_nv; ++j) row[j + 1] = safe_log(lam(std::exp(lth + kVLo + j * kVStep)));
        row[0] = 2 * row[1] - row[2];
        row[nv_ - 1] = 2 * row[nv_ - 2] - row[nv_ - 3];
      }
    });
  });
  // The v rows were padded linearly above: beyond the table log Λ is extrapolated linearly too.
  std::vector<int> dims_p(pn_), dims_v(pn_);
  dims_v.push_back(nv_);
  for (int k = 0; k < d; ++k) {
    pad_axis(log_t_half_, dims_p, k);
    pad_axis(log_lambda_, dims_v, k);
  }
}

bool SmithLambdaTable::covers(const double* params) const {
  for (int k = 0; k < dims(); ++k)
    if (!(params[k] >= axes_[k].lo && params[k] <= axes_[k].hi)) return false;
  return true;
}

}  // namespace brdfkit
