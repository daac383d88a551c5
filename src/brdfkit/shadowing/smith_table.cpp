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

// log(t½ − t_e) with Λ(t½) = 1: Λ grows monotonically with t (from 0 at t_e to ∞), so a bracket
// in u = log(t − t_e) expanded by steps of 2 always closes; Boost's TOMS 748 then converges in ~10
// evaluations.
double log_width(const std::function<double(double)>& lambda_of_t, double t_edge) {
  auto f = [&](double u) { return safe_log(lambda_of_t(t_edge + std::exp(u))); };
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

}  // namespace

struct SmithLambdaTable::Node {
  std::atomic<bool> ready{false};  // fast path: std::call_once costs ~30 ns even when done
  std::once_flag once;
  double log_width = 0.0;
  std::unique_ptr<double[]> row;  // nv_ entries
};

double SmithLambdaTable::log_width_of(const Node& n) { return n.log_width; }
const double* SmithLambdaTable::row_of(const Node& n) { return n.row.get(); }

SmithLambdaTable::SmithLambdaTable(std::vector<SmithAxis> axes, LambdaFn lambda, EdgeFn edge)
    : axes_(std::move(axes)), lambda_(std::move(lambda)), edge_(std::move(edge)) {
  const int d = dims();
  if (d < 1 || d > kMaxDims) throw std::invalid_argument("SmithLambdaTable: 1 to 3 parameter axes");
  for (const auto& a : axes_)
    if (a.n < 4 || !(a.hi > a.lo) || (a.log_scale && !(a.lo > 0.0)))
      throw std::invalid_argument("SmithLambdaTable: bad axis");
  nv_ = static_cast<int>(std::lround((kVHi - kVLo) / kVStep)) + 1 + 2;
  n_nodes_ = 1;
  for (const auto& a : axes_) n_nodes_ *= size_t(a.n);
  nodes_ = std::make_unique<Node[]>(n_nodes_);
}

SmithLambdaTable::~SmithLambdaTable() = default;

const SmithLambdaTable::Node& SmithLambdaTable::node(size_t flat) const {
  Node& n = nodes_[flat];
  if (!n.ready.load(std::memory_order_acquire)) {
    std::call_once(n.once, [&] { build(flat, n); });
    n.ready.store(true, std::memory_order_release);
  }
  return n;
}

void SmithLambdaTable::build(size_t flat, Node& n) const {
  const int d = dims();
  double p[kMaxDims];
  size_t rem = flat;
  for (int k = d - 1; k >= 0; --k) {
    p[k] = axis_value(axes_[k], static_cast<int>(rem % size_t(axes_[k].n)));
    rem /= size_t(axes_[k].n);
  }
  const double t_edge = edge_ ? edge_(p) : 0.0;
  auto lam = [&](double t) { return lambda_(p, t); };
  const double lw = log_width(lam, t_edge);
  auto row = std::make_unique<double[]>(size_t(nv_));
  const int real_nv = nv_ - 2;
  // The row's integrals run in parallel inside an arena isolation: a caller that is itself a TBB
  // task (a parallel fit) must not steal an outer task that waits on this node's std::call_once.
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, real_nv, 16), [&](const tbb::blocked_range<int>& r) {
      for (int j = r.begin(); j != r.end(); ++j) row[j + 1] = safe_log(lam(t_edge + std::exp(lw + kVLo + j * kVStep)));
    });
  });
  // Beyond the table log Λ is extrapolated linearly: linear ghosts keep Catmull-Rom C¹ there.
  row[0] = 2 * row[1] - row[2];
  row[nv_ - 1] = 2 * row[nv_ - 2] - row[nv_ - 3];
  n.log_width = lw;
  n.row = std::move(row);
  built_.fetch_add(1, std::memory_order_relaxed);
}

bool SmithLambdaTable::covers(const double* coords) const {
  for (int k = 0; k < dims(); ++k)
    if (!(coords[k] >= axes_[k].lo && coords[k] <= axes_[k].hi)) return false;
  return true;
}

size_t SmithLambdaTable::nodes_built() const { return built_.load(std::memory_order_relaxed); }

}  // namespace brdfkit
