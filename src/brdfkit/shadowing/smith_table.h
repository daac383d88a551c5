#pragma once
// Tabulated Smith Λ over (distribution parameters, tanθ), so that Λ inside a fit costs tens of ns
// instead of a quadrature (DESIGN.md §4: "tabulated … over a parameter grid, interpolated at run
// time"). Values come from smith_lambda_integral (shadowing/smith_integral.h).
//
// Lazy nodes: a parameter node (its t½ and its row of log Λ over v) is integrated the first time
// an interpolation touches it, once, thread-safely (std::call_once), and kept for the process.
// A fit or a `brdfkit check` at fixed shape parameters therefore pays for the 4^d nodes around
// them (d = number of shape parameters), not for the whole grid: grids can be fine where the
// function needs it (GTR near α = 1) without costing start-up time.
//
// Coordinates, chosen so that the interpolated function is smooth and nearly separable:
//  - each parameter on its own axis, logarithmic for scale-like parameters (α, σ, N + const) and
//    linear for shape parameters (p, γ);
//  - tanθ through v = log(t − t_e) − L(params), where L = log(t½ − t_e), Λ(t½) = 1 (G1 = ½) and
//    t_e is the support edge (Λ = 0 for t ≤ t_e; 0 for every distribution with unbounded slopes,
//    1/tanθ_max for Schlick's rational one, supplied in closed form so Jets carry it). For scale
//    families (Λ(t; α) = Λ₁(α t): Beckmann, GGX, exponential, exponential power at fixed p) the
//    table is then constant along the scale axis and L is linear in log α;
//  - the tabulated value is log Λ: it is linear in v at both ends (log Λ ≈ v + const for t → ∞,
//    and n·v + const for power-law behaviour at the low end, including (t − t_e)^{7/2} at a
//    support edge), where the table is extrapolated linearly; light tails (Beckmann) fall off so
//    fast that G1 = 1 to double precision below the table.
// Interpolation is Catmull-Rom (cubic) along every axis, edge cells through a quadratic ghost node
// (folded into the weights of the real nodes), so ceres::Jet parameters and tanθ carry continuous
// derivatives: Jets get the derivative of the interpolant.
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

#include "brdfkit/ndf/distribution.h"
#include "brdfkit/shadowing/smith_integral.h"

namespace brdfkit {

class SmithLambdaTable {
 public:
  static constexpr int kMaxDims = 3;
  // Grid in v = log(t − t_e) − L and its spacing (accuracy target ~1e-5 on G1, DESIGN.md §4).
  static constexpr double kVLo = -6.0, kVHi = 6.0, kVStep = 0.075;

  // lambda(coords, t): Λ at table coordinates `coords` (in axes order) and t = tanθ.
  // edge(coords): the support edge t_e (Λ = 0 for tanθ ≤ t_e); empty for unbounded slopes.
  using LambdaFn = std::function<double(const double*, double)>;
  using EdgeFn = std::function<double(const double*)>;
  SmithLambdaTable(std::vector<SmithAxis> axes, LambdaFn lambda, EdgeFn edge = {});
  ~SmithLambdaTable();

  int dims() const { return static_cast<int>(axes_.size()); }
  const std::vector<SmithAxis>& axes() const { return axes_; }
  // Whether the coordinates lie inside the tabulated box (outside, callers integrate directly).
  bool covers(const double* coords) const;
  // How many parameter nodes have been integrated so far (lazy build; for tests and reports).
  size_t nodes_built() const;

  // Λ at coordinates `coords` and tanθ; t_edge is the same edge as edge(coords) in T (0 if none).
  template <class T> T lambda(const T* coords, const T& tan_theta, const T& t_edge = T(0)) const;

 private:
  struct Node;
  // The node at real multi-index `flat` (row-major over the axes), integrated on first use.
  const Node& node(size_t flat) const;
  void build(size_t flat, Node& n) const;

  std::vector<SmithAxis> axes_;
  LambdaFn lambda_;
  EdgeFn edge_;
  int nv_ = 0;  // v entries per row: real nodes plus one linear ghost at each end
  std::unique_ptr<Node[]> nodes_;
  size_t n_nodes_ = 0;
  mutable std::atomic<size_t> built_{0};

  template <class T> static void catmull_rom(const T& f, T w[4]) {
    const T f2 = f * f, f3 = f2 * f;
    w[0] = T(0.5) * (-f3 + T(2) * f2 - f);
    w[1] = T(0.5) * (T(3) * f3 - T(5) * f2 + T(2));
    w[2] = T(0.5) * (T(-3) * f3 + T(4) * f2 + f);
    w[3] = T(0.5) * (f3 - f2);
  }
  // Along a parameter axis of n ≥ 4 real nodes at continuous node coordinate x: the first of four
  // consecutive real nodes and their weights. Catmull-Rom's outer neighbour beyond the first or
  // last node is a ghost, the quadratic extrapolation 3f₀ − 3f₁ + f₂ (Catmull-Rom then reproduces
  // quadratics in the edge cells too; a linear ghost made them 30× worse on SGD), folded into the
  // weights of the real nodes.
  // *zero_slot is the slot whose weight is structurally zero (−1 if none): its node is not touched.
  template <class T> static int axis_weights(const T& x, int n, T w[4], int* zero_slot) {
    const int i = std::clamp(static_cast<int>(std::floor(smith_detail::scalar(x))), 0, n - 2);
    T c[4];
    catmull_rom(T(x - T(double(i))), c);  // for nodes i−1 … i+2
    *zero_slot = -1;
    if (i == 0) {
      *zero_slot = 3;
      w[0] = c[1] + T(3) * c[0];
      w[1] = c[2] - T(3) * c[0];
      w[2] = c[3] + c[0];
      w[3] = T(0);
      return 0;
    }
    if (i == n - 2) {
      *zero_slot = 0;
      w[0] = T(0);
      w[1] = c[0] + c[3];
      w[2] = c[1] - T(3) * c[3];
      w[3] = c[2] + T(3) * c[3];
      return n - 4;
    }
    for (int k = 0; k < 4; ++k) w[k] = c[k];
    return i - 1;
  }
  // Row interpolation along v (padded rows: entry j + 1 is real v node j).
  template <class T> static int v_cell(const T& x, int n, T w[4]) {
    const int i = std::clamp(static_cast<int>(std::floor(smith_detail::scalar(x))), 0, n - 2);
    catmull_rom(T(x - T(double(i))), w);
    return i;  // padded entries i .. i+3 = real nodes i−1 .. i+2
  }
  // Scalar access for the templates below (Node is defined in the .cpp).
  static double log_width_of(const Node& n);
  static const double* row_of(const Node& n);

  // The (up to 4^d) parameter nodes around some coordinates and their weights.
  template <class T> struct Term {
    T weight;
    const Node* node;
  };
  template <class T> using Stencil = std::array<Term<T>, 64>;
  // Fills `terms` for `coords`; returns how many. Folded edge weights that are structurally zero
  // are skipped, so no node outside the stencil is ever built.
  template <class T> int stencil(const T* coords, Stencil<T>& terms) const;
  // log Λ at v = log(tanθ − t_edge) − log t½ from the stencil's rows: Catmull-Rom inside the
  // table, linear beyond it.
  template <class T> T log_lambda_at(const Stencil<T>& terms, int n_terms, const T& v) const;
};

template <class T> int SmithLambdaTable::stencil(const T* coords, Stencil<T>& terms) const {
  using std::log;
  const int d = dims();
  int base[kMaxDims] = {0, 0, 0}, zero_slot[kMaxDims] = {-1, -1, -1};
  T w[kMaxDims][4];
  for (int k = 0; k < d; ++k) {
    const SmithAxis& a = axes_[k];
    const T u = a.log_scale ? T((log(coords[k]) - std::log(a.lo)) / (std::log(a.hi) - std::log(a.lo)))
                            : T((coords[k] - a.lo) / (a.hi - a.lo));
    base[k] = axis_weights(T(u * double(a.n - 1)), a.n, w[k], &zero_slot[k]);
  }
  int n_terms = 0;
  const int combos = 1 << (2 * d);
  for (int c = 0; c < combos; ++c) {
    size_t flat = 0;
    T wt(1);
    bool skip = false;
    for (int k = 0; k < d; ++k) {
      const int o = (c >> (2 * k)) & 3;
      skip = skip || o == zero_slot[k];
      flat = flat * size_t(axes_[k].n) + size_t(base[k] + o);
      wt = wt * w[k][o];
    }
    if (!skip) terms[n_terms++] = Term<T>{wt, &node(flat)};
  }
  return n_terms;
}

template <class T> T SmithLambdaTable::log_lambda_at(const Stencil<T>& terms, int n_terms, const T& v) const {
  const int real_nv = nv_ - 2;
  const T xv = (v - T(kVLo)) / T(kVStep);
  // log Λ at real v node jv, interpolated over the parameters.
  auto at_node = [&](int jv) {
    T s(0);
    for (int j = 0; j < n_terms; ++j) s += terms[j].weight * row_of(*terms[j].node)[jv + 1];
    return s;
  };
  const double xs = smith_detail::scalar(xv);
  if (xs < 0.0) {
    const T f0 = at_node(0), f1 = at_node(1);
    return f0 + (f1 - f0) * xv;
  }
  if (xs > real_nv - 1) {
    const int last = real_nv - 1;
    const T f0 = at_node(last - 1), f1 = at_node(last);
    return f1 + (f1 - f0) * (xv - T(double(last)));
  }
  T wv[4];
  const int iv = v_cell(xv, real_nv, wv);
  T log_lambda(0);
  for (int j = 0; j < n_terms; ++j) {
    const double* p = row_of(*terms[j].node) + iv;
    log_lambda += terms[j].weight * (wv[0] * p[0] + wv[1] * p[1] + wv[2] * p[2] + wv[3] * p[3]);
  }
  return log_lambda;
}

template <class T> T SmithLambdaTable::lambda(const T* coords, const T& tan_theta, const T& t_edge) const {
  using std::exp;
  using std::log;
  const T dt = tan_theta - t_edge;
  if (!(smith_detail::scalar(tan_theta) > 0.0) || !(smith_detail::scalar(dt) > 0.0)) return T(0);
  Stencil<T> terms;
  const int n_terms = stencil(coords, terms);
  T log_width(0);
  for (int j = 0; j < n_terms; ++j) log_width += terms[j].weight * log_width_of(*terms[j].node);
  return exp(log_lambda_at(terms, n_terms, T(log(dt) - log_width)));
}

}  // namespace brdfkit
