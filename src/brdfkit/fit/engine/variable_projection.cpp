#include "brdfkit/fit/engine/variable_projection.h"

#include <ceres/ceres.h>
#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>

#include "brdfkit/core/error.h"
#include "brdfkit/fit/engine/box_least_squares.h"
#include "brdfkit/fit/engine/sample_stride.h"
#include "brdfkit/fit/engine/stall_stop.h"
#include "brdfkit/fit/engine/start_scan.h"

namespace brdfkit::fit {

namespace {

using Eigen::Index;

struct Var {
  int param;
  int channel;  // −1: the same value in all three channels
};

// One linear basis function: ρ with linear parameter `lin` = 1, the other linear ones 0, and
// (for a Fresnel-like parameter paired with it) parameter `affine` set to `affine_value`.
struct Basis {
  int lin;
  int affine = -1;
  double affine_value = 0;
};

// The objective at one point of the solver's parameters x: cost = Σ r² (the metric's squared
// residual sum, its scale included), and with derivatives the Gauss-Newton pieces Jᵀr and JᵀJ.
struct Objective {
  double cost = 0;
  Eigen::VectorXd gradient;
  Eigen::MatrixXd jtj;
};

// A chunk of the metric's domain at the current stride (every s-th sample): direction pairs,
// weights and measured values, gathered once per stride.
struct Block {
  size_t n = 0;
  SoaPairs d{};
  const double* m[3] = {};
  std::vector<double> w2;      // (scale · √w · f)² · stride: the identity residual's weight
  std::vector<double> rw, f;   // scale · √w · √stride and f: the transformed residual's parts
  std::vector<double> own;     // gathered arrays (stride > 1)
};

// The fitting problem on a metric's cached domain.
//
// Variable projection (seed 002 §3) solves the per-channel linear parameters (kd, ks) for fixed
// shape. A per-channel parameter P on which ρ depends affinely and only through one linear
// parameter L (Schlick's F0 under ks: ks F = ks F0 + ks (1 − F0)(1 − cosθd)⁵) joins the linear
// sub-problem too (DESIGN.md §12: kd, ks·F0, ks·(1 − F0) are the linear colours): L b(P) =
// u b(P_hi) + v b(P_lo) with u = L t, v = L (1 − t), t = (P − P_lo)/(P_hi − P_lo), u, v ≥ 0; so
// L = u + v and P = P_lo + (P_hi − P_lo) u/(u + v). Both properties are checked numerically.
//
// With the shape x fixed, ρ_c = Σ_j β_cj b_j(x) and the colours β_c minimize Σ w² (B β − m_c)²:
// everything the solver needs is an inner product <a, b> = Σ_k w_k² a_k b_k of the bases b_j,
// their derivatives d_vj = ∂b_j/∂x_v and the measured m_c. One parallel pass per evaluation
// accumulates those Gram matrices; β = the box-constrained solution of <B,B> β = <B,m>; the
// residual r = Bβ − m has (Golub & Pereyra 1973) the Jacobian J_v = d_v β + B ∂β_v, with ∂β_v
// on the free colours F solving <B,B>_FF ∂β_F = <d_v,m> − (<d_v,B> + <B,d_v>) β (active colours
// stay at their bound), so JᵀJ is a few small products of those Gram blocks. Cost and Jᵀr are
// summed directly from the residuals (no cancellation at a near-zero residual).
class Problem {
 public:
  Problem(const Model& model, const Metric& metric) : model_(model), metric_(metric), table_(model.params()) {
    std::vector<int> lin;
    for (size_t p = 0; p < table_.size(); ++p)
      if (table_[p].linear && table_[p].scope == Scope::PerChannel) lin.push_back(int(p));
    if (!homogeneous(lin)) lin.clear();  // no linear sub-problem: every parameter a solver variable
    project_ = metric.transform() == Transform::Identity && !lin.empty();
    std::vector<int> paired(table_.size(), -1);  // P → L
    if (project_) pair_affine(lin, paired);
    if (project_)
      for (int l : lin) {
        int affine = -1;
        for (size_t p = 0; p < table_.size(); ++p)
          if (paired[p] == l) affine = int(p);
        if (affine < 0) bases_.push_back({l});
        else {
          bases_.push_back({l, affine, table_[size_t(affine)].lower});
          bases_.push_back({l, affine, table_[size_t(affine)].upper});
        }
      }
    if (bases_.size() > 6) throw InputError("model '" + std::string(model.name()) + "'", "more than 6 linear parameters");
    for (size_t p = 0; p < table_.size(); ++p) {
      const ParamSpec& s = table_[p];
      if (!(s.upper > s.lower)) continue;  // fixed by its bounds
      if (project_ && ((s.linear && s.scope == Scope::PerChannel) || paired[p] >= 0)) continue;
      if (s.scope == Scope::Shared) vars_.push_back({int(p), -1});
      else
        for (int c = 0; c < 3; ++c) vars_.push_back({int(p), c});
    }
    classes_ = channel_independent() ? 1 : 3;
    if (!project_ && !lin.empty()) setup_transformed(lin);  // a residual not linear in ρ (low-e2)
    for (size_t j = 0; j < bases_.size(); ++j) {
      constant_.push_back(shape_independent(j));
      if (!constant_.back()) varying_.push_back(j);
    }
    set_stride(1);
  }

  const std::vector<Var>& vars() const { return vars_; }
  const ParamTable& table() const { return table_; }
  bool has_linear() const { return project_; }
  size_t sample_count() const {
    size_t n = 0;
    for (size_t i = 0; i < metric_.chunk_count(); ++i) n += chunk(i).size();
    return n;
  }

  void to_values(const double* x, ParamValues& pv) const {
    for (size_t v = 0; v < vars_.size(); ++v)
      for (int c = 0; c < 3; ++c)
        if (vars_[v].channel < 0 || vars_[v].channel == c) pv.values[size_t(c)][size_t(vars_[v].param)] = x[v];
  }
  void from_values(const ParamValues& pv, double* x) const {
    for (size_t v = 0; v < vars_.size(); ++v)
      x[v] = pv.values[size_t(std::max(0, vars_[v].channel))][size_t(vars_[v].param)];
  }

  // Uses every s-th sample of each chunk, weighted s times (s = 1: the whole domain).
  void set_stride(size_t s) {
    if (s == stride_ && !blocks_.empty()) return;
    stride_ = s;
    cache_valid_ = spare_valid_ = last_.valid = false;
    best_ = {};
    const double scale = metric_.scale();
    blocks_.assign(metric_.chunk_count(), Block{});
    tbb::parallel_for(size_t(0), blocks_.size(), [&](size_t i) {
      const MetricChunk& ch = chunk(i);
      Block& b = blocks_[i];
      b.n = (ch.size() + s - 1) / s;
      const double* src[9] = {ch.wi_x.data(), ch.wi_y.data(), ch.wi_z.data(), ch.wo_x.data(), ch.wo_y.data(),
                              ch.wo_z.data(), ch.measured[0].data(), ch.measured[1].data(), ch.measured[2].data()};
      const double* dst[9];
      if (s == 1) {
        std::copy(src, src + 9, dst);
      } else {
        b.own.resize(9 * b.n);
        for (int a = 0; a < 9; ++a) {
          double* out = b.own.data() + size_t(a) * b.n;
          for (size_t k = 0; k < b.n; ++k) out[k] = src[a][k * s];
          dst[a] = out;
        }
      }
      b.d = {dst[0], dst[1], dst[2], dst[3], dst[4], dst[5]};
      for (int c = 0; c < 3; ++c) b.m[c] = dst[6 + c];
      b.w2.resize(b.n);
      b.rw.resize(b.n);
      b.f.resize(b.n);
      for (size_t k = 0; k < b.n; ++k) {
        const double sw = ch.sqrt_weight[k * s], f = ch.factor[k * s];
        b.rw[k] = scale * sw * std::sqrt(double(s));
        b.f[k] = f;
        const double w = b.rw[k] * f;
        b.w2[k] = w * w;
      }
    });
    if (project_) fill_constant_bases();
  }

  // The objective at x; with `solved`, the colours of the projection are written into it (and
  // x's values). False when the model is not finite on the domain.
  bool evaluate(const double* x, bool derivatives, Objective& out, ParamValues* solved = nullptr) {
    // On a bounded problem Ceres' projected line search asks for derivatives at a trial point,
    // then for its cost, then (once accepted) for derivatives there again: the last successful
    // result answers the repeats (the same numbers: the evaluation is deterministic).
    if (last_.valid && (last_.derivatives || !derivatives) && std::equal(last_.x.begin(), last_.x.end(), x)) {
      out = last_.objective;
      if (solved) *solved = last_.solved;
      return true;
    }
    ParamValues pv = base_;
    to_values(x, pv);
    const bool ok = project_  ? evaluate_projected(x, pv, derivatives, out)
                    : tr_.on  ? evaluate_transformed(x, pv, derivatives, out)
                              : evaluate_plain(pv, derivatives, out);
    if (!ok || !std::isfinite(out.cost)) return false;
    if (derivatives && (!out.gradient.allFinite() || !out.jtj.allFinite())) return false;
    if (solved) *solved = pv;
    last_ = {true, derivatives, std::vector<double>(x, x + vars_.size()), out, pv};
    if (out.cost < best_.cost) best_ = {out.cost, last_.x};
    return true;
  }

  // The point of lowest cost evaluated since the last set_stride / set_base (empty: none).
  const std::vector<double>& best_point() const { return best_.x; }

  void set_base(const ParamValues& pv) {
    base_ = pv;
    cache_valid_ = spare_valid_ = last_.valid = false;
    best_ = {};
  }

 private:
  const MetricChunk& chunk(size_t i) const {
    static thread_local MetricChunk unused;
    return metric_.chunk(i, unused);
  }

  // Channel c's parameter vector for basis j: the shape of pv, linear parameters 0 except the
  // basis's own (1) and its paired parameter at the basis's bound.
  std::vector<double> basis_params(const ParamValues& pv, int c, size_t j) const {
    std::vector<double> p = pv.values[size_t(c)];
    for (const Basis& b : bases_) p[size_t(b.lin)] = 0.0;
    p[size_t(bases_[j].lin)] = 1.0;
    if (bases_[j].affine >= 0) p[size_t(bases_[j].affine)] = bases_[j].affine_value;
    return p;
  }

  // Evaluates the bases `js` of class q at the shape of pv on block b into out(j). A Fresnel-like
  // pair (the bases at P_lo and P_hi, adjacent in bases_) takes one Model::eval_batch_pair pass:
  // Cook-Torrance computes D and G once for both (DESIGN.md §12).
  template <class Out> void eval_bases(const ParamValues& pv, int q, const Block& b, const std::vector<size_t>& js,
                                       Out&& out) const {
    for (size_t a = 0; a < js.size(); ++a) {
      const size_t j = js[a];
      const std::vector<double> p = basis_params(pv, q, j);
      const Basis& bj = bases_[j];
      if (bj.affine >= 0 && a + 1 < js.size() && js[a + 1] == j + 1 && bases_[j + 1].lin == bj.lin &&
          bases_[j + 1].affine == bj.affine) {
        model_.eval_batch_pair(p.data(), q, bj.affine, bj.affine_value, bases_[j + 1].affine_value, b.n, b.d, out(j),
                               out(j + 1));
        ++a;
      } else {
        model_.eval_batch(p.data(), q, b.n, b.d, out(j));
      }
    }
  }

  void fill_constant_bases() {
    const size_t K = bases_.size();
    const ParamValues pv = ParamValues::defaults(table_);
    const_bases_.assign(blocks_.size(), {});
    tbb::parallel_for(size_t(0), blocks_.size(), [&](size_t i) {
      const Block& b = blocks_[i];
      auto& store = const_bases_[i];
      store.assign(size_t(classes_) * K, {});
      std::vector<size_t> js;
      for (size_t j = 0; j < K; ++j)
        if (constant_[j]) js.push_back(j);
      for (int q = 0; q < classes_; ++q)
        eval_bases(pv, q, b, js, [&](size_t j) {
          auto& v = store[size_t(q) * K + j];
          v.resize(b.n);
          return v.data();
        });
    });
  }

  void swap_cache() {
    std::swap(cache_, spare_.bases);
    std::swap(cache_x_, spare_.x);
    std::swap(gram_, spare_.gram);
    std::swap(ym_, spare_.ym);
    std::swap(cache_valid_, spare_valid_);
  }

  // Basis j of class q in block i at the cached shape.
  const double* basis(size_t i, int q, size_t j) const {
    const size_t K = bases_.size();
    return constant_[j] ? const_bases_[i][size_t(q) * K + j].data() : cache_[i][size_t(q) * K + j].data();
  }

  // Which classes (basis sets) var v changes: all for a shared var, its channel's otherwise
  // (per-channel shape vars imply one class per channel, see channel_independent()).
  bool affects(const Var& v, int q) const { return v.channel < 0 || v.channel == q; }

  double step(size_t v, double x) const {
    const ParamSpec& s = table_[size_t(vars_[v].param)];
    double h = 1e-6 * std::max(std::abs(x), 1e-3);
    if (x + h > s.upper) h = -h;  // stay inside the bounds
    return h;
  }

  // The forward-difference points x + h_v e_v (parameter values over `base`), one per solver
  // variable, with their steps in h.
  std::vector<ParamValues> shifted_points(const double* x, const ParamValues& base, std::vector<double>& h) const {
    const size_t nv = vars_.size();
    h.assign(nv, 0.0);
    std::vector<ParamValues> points;
    for (size_t v = 0; v < nv; ++v) {
      std::vector<double> xh(x, x + nv);
      h[v] = step(v, x[v]);
      xh[v] += h[v];
      ParamValues ph = base;
      to_values(xh.data(), ph);
      points.push_back(std::move(ph));
    }
    return points;
  }

  bool evaluate_projected(const double* x, ParamValues& pv, bool derivatives, Objective& out) {
    const size_t K = bases_.size(), nv = vars_.size(), nb = blocks_.size();
    const size_t Q = size_t(classes_);
    // 1. Bases at x and their Gram matrices, kept for the last two points: Ceres asks for
    //    derivatives at the point it just accepted, and the fit's result is its last accepted
    //    point, which a rejected trial point may have followed.
    if (cache_valid_ && std::equal(cache_x_.begin(), cache_x_.end(), x)) {
    } else if (spare_valid_ && std::equal(spare_.x.begin(), spare_.x.end(), x)) {
      swap_cache();
    } else {
      swap_cache();  // the current point becomes the spare one
      cache_.assign(nb, {});
      const size_t stride = Q * (K * K + 3 * K);
      std::vector<double> partial(nb * stride, 0.0);
      tbb::parallel_for(size_t(0), nb, [&](size_t i) {
        const Block& b = blocks_[i];
        cache_[i].assign(Q * K, {});
        for (size_t q = 0; q < Q; ++q)
          eval_bases(pv, int(q), b, varying_, [&](size_t j) {
            auto& v = cache_[i][q * K + j];
            v.resize(b.n);
            return v.data();
          });
        double* acc = partial.data() + i * stride;
        for (size_t q = 0; q < Q; ++q) {
          double* G = acc + q * (K * K + 3 * K);
          double* y = G + K * K;  // y[c·K + j] = <b_j, m_c>
          for (size_t j = 0; j < K; ++j) {
            const double* bj = basis(i, int(q), j);
            for (size_t l = j; l < K; ++l) {
              const double* bl = basis(i, int(q), l);
              double s = 0;
              for (size_t k = 0; k < b.n; ++k) s += b.w2[k] * bj[k] * bl[k];
              G[j * K + l] = s;
            }
            for (size_t c = 0; c < 3; ++c) {
              if (Q > 1 && c != q) continue;
              double s = 0;
              for (size_t k = 0; k < b.n; ++k) s += b.w2[k] * bj[k] * b.m[c][k];
              y[c * K + j] = s;
            }
          }
        }
      });
      gram_.assign(Q, Eigen::MatrixXd::Zero(Index(K), Index(K)));
      for (auto& y : ym_) y = Eigen::VectorXd::Zero(Index(K));
      for (size_t i = 0; i < nb; ++i)  // block order: deterministic sums
        for (size_t q = 0; q < Q; ++q) {
          const double* G = partial.data() + i * stride + q * (K * K + 3 * K);
          for (size_t j = 0; j < K; ++j)
            for (size_t l = j; l < K; ++l) gram_[q](Index(j), Index(l)) += G[j * K + l];
          for (size_t c = 0; c < 3; ++c)
            if (Q == 1 || c == q)
              for (size_t j = 0; j < K; ++j) ym_[c][Index(j)] += G[K * K + c * K + j];
        }
      for (auto& G : gram_) G = G.selfadjointView<Eigen::Upper>();
      cache_x_.assign(x, x + nv);
      cache_valid_ = true;
    }
    // 2. The colours.
    Eigen::VectorXd lo = Eigen::VectorXd::Zero(Index(K)), hi = Eigen::VectorXd::Zero(Index(K));
    for (size_t j = 0; j < K; ++j) {
      const ParamSpec& s = table_[size_t(bases_[j].lin)];
      // A paired basis carries u or v ≥ 0; L = u + v is bounded below by 0 (pair_affine checks).
      lo[Index(j)] = bases_[j].affine >= 0 ? 0.0 : s.lower;
      hi[Index(j)] = bases_[j].affine >= 0 ? std::numeric_limits<double>::infinity() : s.upper;
    }
    std::array<Eigen::VectorXd, 3> beta;
    for (int c = 0; c < 3; ++c) {
      const Eigen::MatrixXd& G = gram_[Q == 1 ? 0 : size_t(c)];
      if (!G.allFinite() || !ym_[size_t(c)].allFinite()) return false;
      beta[size_t(c)] = box_least_squares(G, ym_[size_t(c)], lo, hi);
    }
    write_colours(beta, pv);
    // 3. Cost (and, with derivatives, the derivative bases, their Gram blocks and Jᵀr) in one pass.
    // Extended vectors of class q: the K bases, then d_vj for each var v affecting q and j varying.
    std::vector<std::vector<std::pair<size_t, size_t>>> ext(Q);  // (v, j) of each derivative vector
    if (derivatives)
      for (size_t q = 0; q < Q; ++q)
        for (size_t v = 0; v < nv; ++v)
          if (affects(vars_[v], int(q)))
            for (size_t j : varying_) ext[q].push_back({v, j});
    std::vector<size_t> L(Q), offset(Q + 1, 0);
    for (size_t q = 0; q < Q; ++q) {
      L[q] = K + ext[q].size();
      offset[q + 1] = offset[q] + L[q] * L[q] + 3 * L[q];
    }
    const size_t stride = 1 + nv + offset[Q];
    std::vector<double> h;
    const std::vector<ParamValues> shifted = derivatives ? shifted_points(x, base_, h) : std::vector<ParamValues>{};
    std::vector<double> partial(nb * stride, 0.0);
    tbb::parallel_for(size_t(0), nb, [&](size_t i) {
      const Block& b = blocks_[i];
      double* acc = partial.data() + i * stride;
      std::vector<std::vector<double>> dv(Q * nv * K);  // d_vj of class q at [(q·nv + v)·K + j]
      if (derivatives)
        for (size_t q = 0; q < Q; ++q)
          for (size_t v = 0; v < nv; ++v) {
            if (!affects(vars_[v], int(q))) continue;
            eval_bases(shifted[v], int(q), b, varying_, [&](size_t j) {
              auto& d = dv[(q * nv + v) * K + j];
              d.resize(b.n);
              return d.data();
            });
            const double inv = 1.0 / h[v];
            for (size_t j : varying_) {
              double* d = dv[(q * nv + v) * K + j].data();
              const double* b0 = basis(i, int(q), j);
              for (size_t k = 0; k < b.n; ++k) d[k] = (d[k] - b0[k]) * inv;
            }
          }
      std::vector<double> r(b.n), g(b.n);
      for (int c = 0; c < 3; ++c) {
        const size_t q = Q == 1 ? 0 : size_t(c);
        const Eigen::VectorXd& bc = beta[size_t(c)];
        for (size_t k = 0; k < b.n; ++k) r[k] = -b.m[c][k];
        for (size_t j = 0; j < K; ++j) {
          const double* bj = basis(i, int(q), j);
          const double coef = bc[Index(j)];
          for (size_t k = 0; k < b.n; ++k) r[k] += coef * bj[k];
        }
        double cost = 0;
        for (size_t k = 0; k < b.n; ++k) cost += b.w2[k] * r[k] * r[k];
        acc[0] += cost;
        if (!derivatives) continue;
        for (size_t v = 0; v < nv; ++v) {  // Σ w² r (d_v β): Jᵀr without the ∂β term (added below)
          if (!affects(vars_[v], int(q))) continue;
          std::fill(g.begin(), g.end(), 0.0);
          for (size_t j : varying_) {
            const double* d = dv[(q * nv + v) * K + j].data();
            const double coef = bc[Index(j)];
            for (size_t k = 0; k < b.n; ++k) g[k] += coef * d[k];
          }
          double s = 0;
          for (size_t k = 0; k < b.n; ++k) s += b.w2[k] * r[k] * g[k];
          acc[1 + v] += s;
        }
      }
      if (!derivatives) return;
      for (size_t q = 0; q < Q; ++q) {
        std::vector<const double*> e(L[q]);
        for (size_t j = 0; j < K; ++j) e[j] = basis(i, int(q), j);
        for (size_t a = 0; a < ext[q].size(); ++a)
          e[K + a] = dv[(q * nv + ext[q][a].first) * K + ext[q][a].second].data();
        double* G = acc + 1 + nv + offset[q];
        double* y = G + L[q] * L[q];
        for (size_t a = 0; a < L[q]; ++a) {
          for (size_t bb = a; bb < L[q]; ++bb) {
            if (a < K && bb < K) continue;  // the bases' own block is cached already
            double s = 0;
            for (size_t k = 0; k < b.n; ++k) s += b.w2[k] * e[a][k] * e[bb][k];
            G[a * L[q] + bb] = s;
          }
          if (a < K) continue;
          for (size_t c = 0; c < 3; ++c) {
            if (Q > 1 && c != q) continue;
            double s = 0;
            for (size_t k = 0; k < b.n; ++k) s += b.w2[k] * e[a][k] * b.m[c][k];
            y[c * L[q] + a] = s;
          }
        }
      }
    });
    out.cost = 0;
    out.gradient = Eigen::VectorXd::Zero(Index(nv));
    out.jtj = Eigen::MatrixXd::Zero(Index(nv), Index(nv));
    std::vector<Eigen::MatrixXd> E(Q);
    std::vector<std::array<Eigen::VectorXd, 3>> Ey(Q);
    for (size_t q = 0; q < Q; ++q) {
      E[q] = Eigen::MatrixXd::Zero(Index(L[q]), Index(L[q]));
      for (auto& y : Ey[q]) y = Eigen::VectorXd::Zero(Index(L[q]));
    }
    for (size_t i = 0; i < nb; ++i) {  // block order: deterministic sums
      const double* acc = partial.data() + i * stride;
      out.cost += acc[0];
      if (!derivatives) continue;
      for (size_t v = 0; v < nv; ++v) out.gradient[Index(v)] += acc[1 + v];
      for (size_t q = 0; q < Q; ++q) {
        const double* G = acc + 1 + nv + offset[q];
        for (size_t a = 0; a < L[q]; ++a) {
          for (size_t bb = a; bb < L[q]; ++bb) E[q](Index(a), Index(bb)) += G[a * L[q] + bb];
          for (size_t c = 0; c < 3; ++c) Ey[q][c][Index(a)] += G[L[q] * L[q] + c * L[q] + a];
        }
      }
    }
    if (!derivatives) return true;
    for (size_t q = 0; q < Q; ++q) {
      E[q].topLeftCorner(Index(K), Index(K)) = gram_[q];
      E[q] = E[q].selfadjointView<Eigen::Upper>();
    }
    // 4. Jacobian of the projected residual (Golub-Pereyra), per channel, from the Gram blocks.
    for (int c = 0; c < 3; ++c) {
      const size_t q = Q == 1 ? 0 : size_t(c);
      const Eigen::VectorXd& bc = beta[size_t(c)];
      const Eigen::MatrixXd& G = gram_[q];
      std::vector<Index> free;
      for (size_t j = 0; j < K; ++j)
        if (bc[Index(j)] > lo[Index(j)] && bc[Index(j)] < hi[Index(j)]) free.push_back(Index(j));
      Eigen::MatrixXd Gff(Index(free.size()), Index(free.size()));
      for (size_t a = 0; a < free.size(); ++a)
        for (size_t bb = 0; bb < free.size(); ++bb) Gff(Index(a), Index(bb)) = G(free[a], free[bb]);
      Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> solver;
      if (!free.empty()) solver.compute(Gff);
      // Index in E[q] of d_vj, or −1 when b_j does not vary.
      auto at = [&](size_t v, size_t j) -> Index {
        for (size_t a = 0; a < ext[q].size(); ++a)
          if (ext[q][a].first == v && ext[q][a].second == j) return Index(K + a);
        return -1;
      };
      std::vector<size_t> vs;
      for (size_t v = 0; v < nv; ++v)
        if (affects(vars_[v], int(q))) vs.push_back(v);
      // g_v = d_v β as coefficients over E's columns; ∂β_v over the bases.
      std::vector<Eigen::VectorXd> gv, dbeta;
      for (size_t v : vs) {
        Eigen::VectorXd coef = Eigen::VectorXd::Zero(Index(L[q]));
        for (size_t j : varying_) coef[at(v, j)] = bc[Index(j)];
        // ∂y − ∂G β with ∂G = <d_v, B> + <B, d_v>.
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(Index(K));
        for (size_t j = 0; j < K; ++j) {
          const Index dj = constant_[j] ? -1 : at(v, j);
          double s = dj >= 0 ? Ey[q][size_t(c)][dj] : 0.0;
          for (size_t l = 0; l < K; ++l) {
            const Index dl = constant_[l] ? -1 : at(v, l);
            double dG = 0;
            if (dj >= 0) dG += E[q](dj, Index(l));
            if (dl >= 0) dG += E[q](Index(j), dl);
            s -= dG * bc[Index(l)];
          }
          rhs[Index(j)] = s;
        }
        Eigen::VectorXd db = Eigen::VectorXd::Zero(Index(K));
        if (!free.empty()) {
          Eigen::VectorXd rf(Index(free.size()));
          for (size_t a = 0; a < free.size(); ++a) rf[Index(a)] = rhs[free[a]];
          const Eigen::VectorXd sf = solver.solve(rf);
          for (size_t a = 0; a < free.size(); ++a) db[free[a]] = sf[Index(a)];
        }
        gv.push_back(coef);
        dbeta.push_back(db);
      }
      const Eigen::MatrixXd EB = E[q].leftCols(Index(K));  // <e_a, b_l>
      const Eigen::VectorXd resid_grad = G * bc - ym_[size_t(c)];  // <B, r>: 0 on the free colours
      for (size_t a = 0; a < vs.size(); ++a) {
        out.gradient[Index(vs[a])] += dbeta[a].dot(resid_grad);
        for (size_t bb = 0; bb < vs.size(); ++bb) {
          const double t = gv[a].dot(E[q] * gv[bb]) + gv[a].dot(EB * dbeta[bb]) + gv[bb].dot(EB * dbeta[a]) +
                           dbeta[a].dot(G * dbeta[bb]);
          out.jtj(Index(vs[a]), Index(vs[bb])) += t;
        }
      }
    }
    return true;
  }

  // Every parameter a solver variable (a residual not linear in ρ, or no colour): the residual
  // r = rw (T(f ρ) − T(f m)) and its forward-difference Jacobian, reduced per block to JᵀJ, Jᵀr.
  bool evaluate_plain(const ParamValues& pv, bool derivatives, Objective& out) {
    const size_t nv = vars_.size(), nb = blocks_.size();
    const Transform t = metric_.transform();
    const size_t stride = 1 + nv + nv * nv;
    std::vector<double> x(nv), h;
    from_values(pv, x.data());
    const std::vector<ParamValues> shifted = derivatives ? shifted_points(x.data(), pv, h) : std::vector<ParamValues>{};
    std::vector<double> partial(nb * stride, 0.0);
    tbb::parallel_for(size_t(0), nb, [&](size_t i) {
      const Block& b = blocks_[i];
      double* acc = partial.data() + i * stride;
      std::vector<double> rho(b.n), r(3 * b.n), J(derivatives ? nv * 3 * b.n : 0, 0.0);
      auto residual = [&](const ParamValues& p, int c, double* dst) {
        model_.eval_batch(p.channel(c), c, b.n, b.d, rho.data());
        for (size_t k = 0; k < b.n; ++k)
          dst[k] = b.rw[k] * (apply_transform(t, b.f[k] * rho[k]) - apply_transform(t, b.f[k] * b.m[c][k]));
      };
      for (int c = 0; c < 3; ++c) residual(pv, c, r.data() + size_t(c) * b.n);
      for (double v : r) acc[0] += v * v;
      if (!derivatives) return;
      for (size_t v = 0; v < nv; ++v)
        for (int c = 0; c < 3; ++c) {
          if (!affects(vars_[v], c)) continue;
          double* Jv = J.data() + (v * 3 + size_t(c)) * b.n;
          residual(shifted[v], c, Jv);
          const double* r0 = r.data() + size_t(c) * b.n;
          const double inv = 1.0 / h[v];
          for (size_t k = 0; k < b.n; ++k) Jv[k] = (Jv[k] - r0[k]) * inv;
        }
      for (size_t u = 0; u < nv; ++u) {
        const double* Ju = J.data() + u * 3 * b.n;
        double s = 0;
        for (size_t k = 0; k < 3 * b.n; ++k) s += Ju[k] * r[k];
        acc[1 + u] = s;
        for (size_t v = u; v < nv; ++v) {
          const double* Jv = J.data() + v * 3 * b.n;
          double s2 = 0;
          for (size_t k = 0; k < 3 * b.n; ++k) s2 += Ju[k] * Jv[k];
          acc[1 + nv + u * nv + v] = s2;
        }
      }
    });
    out.cost = 0;
    out.gradient = Eigen::VectorXd::Zero(Index(nv));
    out.jtj = Eigen::MatrixXd::Zero(Index(nv), Index(nv));
    for (size_t i = 0; i < nb; ++i) {  // block order: deterministic sums
      const double* acc = partial.data() + i * stride;
      out.cost += acc[0];
      if (!derivatives) continue;
      for (size_t u = 0; u < nv; ++u) {
        out.gradient[Index(u)] += acc[1 + u];
        for (size_t v = u; v < nv; ++v) out.jtj(Index(u), Index(v)) += acc[1 + nv + u * nv + v];
      }
    }
    if (derivatives) out.jtj = out.jtj.selfadjointView<Eigen::Upper>();
    return true;
  }

  // ---- A residual not linear in ρ (low-e2's ln(1 + ·), seed 003 Eq. 32) -------------------
  // The colours cannot be projected out, so they stay solver variables (seed 003 §5.1 fits every
  // parameter of E2 at once), but ρ is still linear in them: ρ_c = Σ_j β_cj b_j(s), b_j the model
  // with colour j = 1 and the others 0 at the shape s. So the model is evaluated only for the
  // bases (once for R, G and B when it ignores the channel; a basis that no shape variable moves,
  // like Lambert's 1/π, once per stride), the colour columns of the Jacobian are exact
  // (∂r/∂β_cj = r′ b_j with r′ = rw f T′(f ρ)), and only the shape columns take forward differences,
  // of the bases: ∂r/∂s_v = r′ Σ_j β_cj ∂b_j/∂s_v. T(f m) is computed once per stride.
  void setup_transformed(const std::vector<int>& lin) {
    tr_.on = true;
    tr_.lin = lin;
    std::vector<int> colour_of(table_.size(), -1);
    for (size_t j = 0; j < lin.size(); ++j) colour_of[size_t(lin[j])] = int(j);
    for (auto& v : tr_.var_of) v.assign(lin.size(), -1);
    for (size_t v = 0; v < vars_.size(); ++v) {
      const int j = colour_of[size_t(vars_[v].param)];
      if (j >= 0) tr_.var_of[size_t(vars_[v].channel)][size_t(j)] = int(v);  // per-channel: channel ≥ 0
      else tr_.shape.push_back(v);
    }
    // One basis set for R, G, B when no shape variable is per channel and the model ignores the
    // channel (probed; evaluate_transformed also compares the channels' parameters).
    tr_.channel_free = true;
    for (size_t v : tr_.shape) tr_.channel_free = tr_.channel_free && vars_[v].channel < 0;
    const ParamValues pv = ParamValues::defaults(table_);
    for (size_t j = 0; j < lin.size() && tr_.channel_free; ++j)
      tr_.channel_free = same_in_every_channel(tr_params(pv, 0, j));
    // A basis is constant when moving every shape variable (to a point inside its bounds) leaves
    // it unchanged at the probes.
    tr_.constant.assign(lin.size(), true);
    for (size_t j = 0; j < lin.size(); ++j)
      for (int c = 0; c < 3 && tr_.constant[j]; ++c) {
        const std::vector<double> a = tr_params(pv, c, j);
        std::vector<double> b = a;
        for (size_t v : tr_.shape) {
          const ParamSpec& s = table_[size_t(vars_[v].param)];
          if (affects(vars_[v], c)) b[size_t(vars_[v].param)] = s.lower + 0.371 * (s.upper - s.lower);
        }
        for (int k = 0; k < 12 && tr_.constant[j]; ++k) {
          const auto [wi, wo] = probe(k);
          tr_.constant[j] = model_.eval(a.data(), c, wi, wo) == model_.eval(b.data(), c, wi, wo);
        }
      }
  }

  // Channel c's parameters of transformed basis j: colour j = 1, the other colours 0.
  std::vector<double> tr_params(const ParamValues& pv, int c, size_t j) const {
    std::vector<double> p = pv.values[size_t(c)];
    for (int l : tr_.lin) p[size_t(l)] = 0.0;
    p[size_t(tr_.lin[j])] = 1.0;
    return p;
  }

  // Basis classes at pv: 1 when R, G, B share one basis set, else 3.
  size_t tr_classes(const ParamValues& pv) const {
    if (!tr_.channel_free) return 3;
    for (size_t j = 0; j < tr_.lin.size(); ++j)
      for (int c = 1; c < 3; ++c)
        if (tr_params(pv, c, j) != tr_params(pv, 0, j)) return 3;
    return 1;
  }

  // Makes tr_.bases hold every basis at pv's shape on the current stride (constant bases at the
  // table's default shape, evaluated once per stride), and tr_.tm = T(f m) per block and channel.
  void tr_prepare(const ParamValues& pv, size_t Q) {
    const size_t K = tr_.lin.size(), nb = blocks_.size();
    const Transform t = metric_.transform();
    if (tr_.stride != stride_ || tr_.blocks != nb) {
      tr_.stride = stride_;
      tr_.blocks = nb;
      tr_.keys.assign(3 * K, {});
      tr_.bases.assign(nb, std::vector<std::vector<double>>(3 * K));
      tr_.tm.assign(nb, {});
      tbb::parallel_for(size_t(0), nb, [&](size_t i) {
        const Block& b = blocks_[i];
        tr_.tm[i].resize(3 * b.n);
        for (int c = 0; c < 3; ++c)
          for (size_t k = 0; k < b.n; ++k) tr_.tm[i][size_t(c) * b.n + k] = apply_transform(t, b.f[k] * b.m[c][k]);
      });
    }
    const ParamValues defaults = ParamValues::defaults(table_);
    std::vector<std::pair<size_t, std::vector<double>>> todo;  // (q·K + j, parameters)
    for (size_t q = 0; q < Q; ++q)
      for (size_t j = 0; j < K; ++j) {
        std::vector<double> p = tr_params(pv, int(q), j);
        if (tr_.constant[j])  // the shape variables at their defaults: one key per stride
          for (size_t v : tr_.shape) p[size_t(vars_[v].param)] = defaults.values[q][size_t(vars_[v].param)];
        if (tr_.keys[q * K + j] != p) todo.push_back({q * K + j, std::move(p)});
      }
    if (todo.empty()) return;
    tbb::parallel_for(size_t(0), nb, [&](size_t i) {
      const Block& b = blocks_[i];
      for (const auto& [qj, p] : todo) {
        auto& v = tr_.bases[i][qj];
        v.resize(b.n);
        model_.eval_batch(p.data(), int(qj / K), b.n, b.d, v.data());
      }
    });
    for (auto& [qj, p] : todo) tr_.keys[qj] = std::move(p);
  }

  bool evaluate_transformed(const double* x, const ParamValues& pv, bool derivatives, Objective& out) {
    const size_t K = tr_.lin.size(), nv = vars_.size(), nb = blocks_.size(), S = tr_.shape.size();
    const size_t Q = tr_classes(pv);
    tr_prepare(pv, Q);
    std::vector<double> h;
    const std::vector<ParamValues> shifted = derivatives ? shifted_points(x, base_, h) : std::vector<ParamValues>{};
    // Columns of channel c: its K colours, then the shape variables that affect it.
    std::array<std::vector<int>, 3> cols;
    std::array<std::vector<size_t>, 3> shape_of;  // indices into tr_.shape
    for (int c = 0; c < 3; ++c) {
      cols[size_t(c)] = tr_.var_of[size_t(c)];
      for (size_t s = 0; s < S; ++s)
        if (affects(vars_[tr_.shape[s]], c)) {
          cols[size_t(c)].push_back(int(tr_.shape[s]));
          shape_of[size_t(c)].push_back(s);
        }
    }
    const size_t M = K + S;  // an upper bound of every channel's column count
    const size_t stride = 3 * (1 + M + M * M);
    std::vector<double> partial(nb * stride, 0.0);
    std::array<std::vector<double>, 3> beta;
    for (int c = 0; c < 3; ++c)
      for (size_t j = 0; j < K; ++j) beta[size_t(c)].push_back(pv.values[size_t(c)][size_t(tr_.lin[j])]);
    tbb::parallel_for(size_t(0), nb, [&](size_t i) {
      const Block& b = blocks_[i];
      // ∂b_j/∂s of each class by forward differences (constant bases have none).
      std::vector<std::vector<double>> d(derivatives ? Q * S * K : 0);  // [(q·S + s)·K + j]
      for (size_t q = 0; q < Q && derivatives; ++q)
        for (size_t s = 0; s < S; ++s) {
          const size_t v = tr_.shape[s];
          if (!affects(vars_[v], int(q))) continue;
          const double inv = 1.0 / h[v];
          for (size_t j = 0; j < K; ++j) {
            if (tr_.constant[j]) continue;
            auto& dj = d[(q * S + s) * K + j];
            dj.resize(b.n);
            const std::vector<double> p = tr_params(shifted[v], int(q), j);
            model_.eval_batch(p.data(), int(q), b.n, b.d, dj.data());
            const double* b0 = tr_.bases[i][q * K + j].data();
            for (size_t k = 0; k < b.n; ++k) dj[k] = (dj[k] - b0[k]) * inv;
          }
        }
      std::vector<double> a(M);
      for (int c = 0; c < 3; ++c) {
        const size_t q = Q == 1 ? 0 : size_t(c);
        double* acc = partial.data() + i * stride + size_t(c) * (1 + M + M * M);
        double* grad = acc + 1;
        double* jtj = grad + M;
        const size_t mc = cols[size_t(c)].size();
        const double* tm = tr_.tm[i].data() + size_t(c) * b.n;
        std::vector<const double*> bj(K);
        for (size_t j = 0; j < K; ++j) bj[j] = tr_.bases[i][q * K + j].data();
        const std::vector<double>& bc = beta[size_t(c)];
        double cost = 0;
        for (size_t k = 0; k < b.n; ++k) {
          double rho = 0;
          for (size_t j = 0; j < K; ++j) rho += bc[j] * bj[j][k];
          const double z = b.f[k] * rho;
          const double r = b.rw[k] * (apply_transform(metric_.transform(), z) - tm[k]);
          cost += r * r;
          if (!derivatives) continue;
          const double slope = b.rw[k] * b.f[k] * transform_slope(metric_.transform(), z);
          for (size_t j = 0; j < K; ++j) a[j] = slope * bj[j][k];
          for (size_t m = K; m < mc; ++m) {
            const size_t s = shape_of[size_t(c)][m - K];
            double drho = 0;
            for (size_t j = 0; j < K; ++j)
              if (!tr_.constant[j]) drho += bc[j] * d[(q * S + s) * K + j][k];
            a[m] = slope * drho;
          }
          for (size_t m = 0; m < mc; ++m) {
            grad[m] += a[m] * r;
            for (size_t l = m; l < mc; ++l) jtj[m * M + l] += a[m] * a[l];
          }
        }
        acc[0] = cost;
      }
    });
    out.cost = 0;
    out.gradient = Eigen::VectorXd::Zero(Index(nv));
    out.jtj = Eigen::MatrixXd::Zero(Index(nv), Index(nv));
    for (size_t i = 0; i < nb; ++i)  // block order: deterministic sums
      for (size_t c = 0; c < 3; ++c) {
        const double* acc = partial.data() + i * stride + c * (1 + M + M * M);
        out.cost += acc[0];
        if (!derivatives) continue;
        const std::vector<int>& col = cols[c];
        for (size_t m = 0; m < col.size(); ++m) {
          if (col[m] < 0) continue;  // a colour fixed by its bounds
          out.gradient[col[m]] += acc[1 + m];
          for (size_t l = m; l < col.size(); ++l) {
            if (col[l] < 0) continue;
            const double v = acc[1 + M + m * M + l];
            out.jtj(col[m], col[l]) += v;
            if (col[l] != col[m]) out.jtj(col[l], col[m]) += v;
          }
        }
      }
    return true;
  }

 public:
  // Under a transformed residual, sets pv's colours to the best ones for pv's shape under the
  // residual linearized about the data, T(f ρ) − T(f m) ≈ T′(f m) f (ρ − m): a weighted
  // bound-constrained linear solve per channel on the current stride, so every start begins
  // with colours that fit its shape. No-op for other residuals.
  void start_colours(ParamValues& pv) {
    if (!tr_.on) return;
    const size_t K = tr_.lin.size(), nb = blocks_.size();
    const size_t Q = tr_classes(pv);
    tr_prepare(pv, Q);
    const size_t stride = 3 * (K * K + K);
    std::vector<double> partial(nb * stride, 0.0);
    tbb::parallel_for(size_t(0), nb, [&](size_t i) {
      const Block& b = blocks_[i];
      for (int c = 0; c < 3; ++c) {
        const size_t q = Q == 1 ? 0 : size_t(c);
        double* G = partial.data() + i * stride + size_t(c) * (K * K + K);
        for (size_t k = 0; k < b.n; ++k) {
          const double fm = b.f[k] * b.m[c][k];
          const double w = b.rw[k] * b.f[k] * transform_slope(metric_.transform(), std::max(fm, 0.0));
          const double w2 = w * w;
          for (size_t j = 0; j < K; ++j) {
            const double bj = tr_.bases[i][q * K + j][k];
            for (size_t l = j; l < K; ++l) G[j * K + l] += w2 * bj * tr_.bases[i][q * K + l][k];
            G[K * K + j] += w2 * bj * b.m[c][k];
          }
        }
      }
    });
    for (int c = 0; c < 3; ++c) {
      Eigen::MatrixXd G = Eigen::MatrixXd::Zero(Index(K), Index(K));
      Eigen::VectorXd y = Eigen::VectorXd::Zero(Index(K)), lo = y, hi = y;
      for (size_t i = 0; i < nb; ++i) {  // block order: deterministic sums
        const double* g = partial.data() + i * stride + size_t(c) * (K * K + K);
        for (size_t j = 0; j < K; ++j) {
          for (size_t l = j; l < K; ++l) G(Index(j), Index(l)) += g[j * K + l];
          y[Index(j)] += g[K * K + j];
        }
      }
      G = G.selfadjointView<Eigen::Upper>();
      for (size_t j = 0; j < K; ++j) {
        lo[Index(j)] = table_[size_t(tr_.lin[j])].lower;
        hi[Index(j)] = table_[size_t(tr_.lin[j])].upper;
      }
      if (!G.allFinite() || !y.allFinite()) return;
      const Eigen::VectorXd beta = box_least_squares(G, y, lo, hi);
      for (size_t j = 0; j < K; ++j) pv.values[size_t(c)][size_t(tr_.lin[j])] = beta[Index(j)];
    }
  }

 private:
  // β (per channel, per basis) → parameter values: linear ones directly, a pair (v, u) as
  // L = u + v, P = P_lo + (P_hi − P_lo) u/(u + v).
  void write_colours(const std::array<Eigen::VectorXd, 3>& beta, ParamValues& pv) const {
    for (int c = 0; c < 3; ++c) {
      auto& v = pv.values[size_t(c)];
      for (size_t j = 0; j < bases_.size(); ++j) {
        const Basis& b = bases_[j];
        if (b.affine < 0) {
          v[size_t(b.lin)] = beta[size_t(c)][Index(j)];
        } else if (b.affine_value == table_[size_t(b.affine)].lower) {  // the pair (v, u) starts here
          const double lo_coef = beta[size_t(c)][Index(j)], hi_coef = beta[size_t(c)][Index(j + 1)];
          const ParamSpec& L = table_[size_t(b.lin)];
          const ParamSpec& P = table_[size_t(b.affine)];
          const double sum = lo_coef + hi_coef;
          // L above its upper bound is clamped (documented limitation of the pairing).
          v[size_t(b.lin)] = std::min(sum, L.upper);
          if (sum > 0) v[size_t(b.affine)] = P.lower + (P.upper - P.lower) * hi_coef / sum;
        }
      }
    }
  }

  // Fixed probe direction pairs, away from the mirror direction and from the horizon.
  static std::pair<Vec3d, Vec3d> probe(int k) {
    return {spherical_direction(0.05 + 0.09 * k, 0.0), spherical_direction(0.1 + 0.08 * k, 0.4 * k)};
  }

  void pair_affine(const std::vector<int>& lin, std::vector<int>& paired) const {
    const ParamValues defaults = ParamValues::defaults(table_);
    for (size_t P = 0; P < table_.size(); ++P) {
      const ParamSpec& s = table_[P];
      if (s.linear || s.scope != Scope::PerChannel || !(s.upper > s.lower) || !std::isfinite(s.lower) ||
          !std::isfinite(s.upper))
        continue;
      for (int L : lin) {
        if (table_[size_t(L)].lower != 0.0 || std::count(paired.begin(), paired.end(), L)) continue;
        bool affine = true, only_through_L = true, depends = false;
        for (int c = 0; c < 3 && affine && only_through_L; ++c)
          for (int k = 0; k < 12 && affine && only_through_L; ++k) {
            const auto [wi, wo] = probe(k);
            auto at = [&](double l_value, double others, double p_value) {
              std::vector<double> p = defaults.values[size_t(c)];
              for (int l : lin) p[size_t(l)] = others;
              p[size_t(L)] = l_value;
              p[P] = p_value;
              return model_.eval(p.data(), c, wi, wo);
            };
            const double a = at(1, 0, s.lower), b = at(1, 0, s.upper), mid = at(1, 0, 0.5 * (s.lower + s.upper));
            affine = std::abs(mid - 0.5 * (a + b)) <= 1e-9 * (std::abs(a) + std::abs(b)) + 1e-300;
            depends = depends || a != b;
            only_through_L = at(0, 1, s.lower) == at(0, 1, s.upper);
          }
        if (affine && only_through_L && depends) {
          paired[P] = L;
          break;
        }
      }
    }
  }

  // Whether basis j is the same for every value of the solver's parameters (probed at the
  // defaults and at another point of the bounds): then it is evaluated once per stride.
  bool shape_independent(size_t j) const {
    const ParamValues pv = ParamValues::defaults(table_);
    for (int c = 0; c < classes_; ++c) {
      const std::vector<double> a = basis_params(pv, c, j);
      std::vector<double> b = a;
      for (const Var& v : vars_) {
        const ParamSpec& s = table_[size_t(v.param)];
        if (v.channel < 0 || v.channel == c) b[size_t(v.param)] = s.lower + 0.371 * (s.upper - s.lower);
      }
      for (int k = 0; k < 12; ++k) {
        const auto [wi, wo] = probe(k);
        if (model_.eval(a.data(), c, wi, wo) != model_.eval(b.data(), c, wi, wo)) return false;
      }
    }
    return true;
  }

  // Whether ρ vanishes with every linear parameter at 0 (probed): the projection writes ρ as
  // Σ β_j b_j, which a term free of them breaks. Ashikhmin-Shirley's lobe (colour Rs, a Schlick
  // F0, no scale) is such a term: fitted as kd (1/π + lobe) it stalled at shape error 0.94.
  bool homogeneous(const std::vector<int>& lin) const {
    const ParamValues pv = ParamValues::defaults(table_);
    for (int c = 0; c < 3; ++c) {
      std::vector<double> p = pv.values[size_t(c)];
      for (int l : lin) p[size_t(l)] = 0.0;
      for (int k = 0; k < 12; ++k) {
        const auto [wi, wo] = probe(k);
        if (model_.eval(p.data(), c, wi, wo) != 0.0) return false;
      }
    }
    return true;
  }

  // Whether channel c changes the model's value at equal parameters (wavelength-dependent
  // models do): probed at a few fixed direction pairs; if not, one basis serves R, G and B.
  bool channel_independent() const {
    for (const Var& v : vars_)
      if (v.channel >= 0) return false;
    const ParamValues pv = ParamValues::defaults(table_);
    std::vector<double> p = pv.values[0];
    for (const Basis& b : bases_) p[size_t(b.lin)] = 1.0;
    return same_in_every_channel(p);
  }

  // Whether the model gives channels 1 and 2 the value of channel 0 at parameters p (probed).
  bool same_in_every_channel(const std::vector<double>& p) const {
    for (int k = 0; k < 16; ++k) {
      const auto [wi, wo] = probe(k);
      const double v0 = model_.eval(p.data(), 0, wi, wo);
      for (int c = 1; c < 3; ++c)
        if (model_.eval(p.data(), c, wi, wo) != v0) return false;
    }
    return true;
  }

  const Model& model_;
  const Metric& metric_;
  ParamTable table_;
  ParamValues base_;
  bool project_ = false;
  std::vector<Basis> bases_;
  std::vector<Var> vars_;
  int classes_ = 3;
  std::vector<bool> constant_;
  std::vector<size_t> varying_;  // the bases that are not constant
  size_t stride_ = 0;
  std::vector<Block> blocks_;
  std::vector<std::vector<std::vector<double>>> const_bases_, cache_;  // [block][q·K + j][sample]
  bool cache_valid_ = false;
  std::vector<double> cache_x_;
  std::vector<Eigen::MatrixXd> gram_;             // <B, B> per class, at cache_x_
  std::array<Eigen::VectorXd, 3> ym_;             // <B, m_c> per channel, at cache_x_
  struct {
    std::vector<std::vector<std::vector<double>>> bases;
    std::vector<double> x;
    std::vector<Eigen::MatrixXd> gram;
    std::array<Eigen::VectorXd, 3> ym;
  } spare_;  // the point cached before cache_x_
  bool spare_valid_ = false;
  struct {
    bool valid = false;
    bool derivatives = false;
    std::vector<double> x;
    Objective objective;
    ParamValues solved;
  } last_;  // the last successful evaluate(), at the current stride and base
  struct {
    double cost = std::numeric_limits<double>::infinity();
    std::vector<double> x;
  } best_;  // the lowest-cost successful evaluate() at the current stride and base
  struct {
    bool on = false;                       // a transformed residual with colours (evaluate_transformed)
    std::vector<int> lin;                  // the colour parameters: basis j has colour lin[j] = 1
    std::array<std::vector<int>, 3> var_of;  // solver variable of colour j in channel c (−1: fixed)
    std::vector<size_t> shape;             // solver variables that are not colours
    bool channel_free = false;
    std::vector<bool> constant;            // basis j does not depend on the shape
    size_t stride = 0, blocks = 0;         // what bases and tm were built for
    std::vector<std::vector<double>> keys;  // [q·K + j]: the parameters tr_.bases holds
    std::vector<std::vector<std::vector<double>>> bases;  // [block][q·K + j][sample]
    std::vector<std::vector<double>> tm;    // [block][c·n + k] = T(f m_c)
  } tr_;
};

// The objective as a Ceres problem of n + 1 residuals instead of the domain's millions: with
// JᵀJ = Q Λ Qᵀ, the residuals r̃ = Λ^{-½} Qᵀ Jᵀr and e = √(cost − |r̃|²) with Jacobian [Λ^{½} Qᵀ; 0]
// have the same cost, gradient and Gauss-Newton matrix as the full residual, so every
// Levenberg-Marquardt step and acceptance test is the one the full problem would take.
class CompressedCost final : public ceres::CostFunction {
 public:
  explicit CompressedCost(Problem& problem) : problem_(problem), n_(problem.vars().size()) {
    set_num_residuals(int(n_ + 1));
    mutable_parameter_block_sizes()->push_back(int(n_));
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const bool derivatives = jacobians && jacobians[0];
    Objective o;
    if (!problem_.evaluate(parameters[0], derivatives, o)) return false;
    std::fill(residuals, residuals + n_ + 1, 0.0);
    if (!derivatives) {
      residuals[n_] = std::sqrt(o.cost);
      return true;
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(o.jtj);
    const Eigen::VectorXd& lambda = eig.eigenvalues();
    const Eigen::MatrixXd& Q = eig.eigenvectors();
    const double floor = 1e-14 * std::max(lambda.cwiseAbs().maxCoeff(), 1e-300);
    double* J = jacobians[0];  // row-major (n + 1) × n
    std::fill(J, J + (n_ + 1) * n_, 0.0);
    double projected = 0;
    for (size_t i = 0; i < n_; ++i) {
      const double l = lambda[Index(i)];
      if (!(l > floor)) continue;
      const double s = std::sqrt(l);
      residuals[i] = Q.col(Index(i)).dot(o.gradient) / s;
      projected += residuals[i] * residuals[i];
      for (size_t v = 0; v < n_; ++v) J[i * n_ + v] = s * Q(Index(v), Index(i));
    }
    residuals[n_] = std::sqrt(std::max(0.0, o.cost - projected));
    return true;
  }

 private:
  Problem& problem_;
  size_t n_;
};

double draw(const ParamSpec& s, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double t = u(rng);
  if (!std::isfinite(s.lower) || !std::isfinite(s.upper)) return s.def;
  if (s.lower > 0 && s.upper / s.lower > 100) return s.lower * std::pow(s.upper / s.lower, t);
  return s.lower + t * (s.upper - s.lower);
}

// Sample strides of the coarse-to-fine levels (67, 17, 7: fit/sample_stride.h), the whole domain
// (1) last.
std::vector<size_t> levels(size_t samples, bool coarse_to_fine) {
  std::vector<size_t> out;
  if (coarse_to_fine)
    for (size_t s : {64, 16, 4})
      if (samples / coprime_stride(s) >= 30000) out.push_back(coprime_stride(s));
  out.push_back(1);
  return out;
}

}  // namespace

FitResult fit_model(const Model& model, const Metric& metric, const FitOptions& options) {
  if (options.starts < 1) throw InputError("--starts", "must be at least 1");
  if (options.max_iterations < 1) throw InputError("--max-iterations", "must be at least 1");
  if (!metric.cached())
    throw InputError("metric '" + std::string(metric.id()) + "'",
                     "is for reports only (its grid is too large to keep); fit under ngan, bagher, low-e1 or low-e2");
  metric.check_model(model);
  const auto t0 = std::chrono::steady_clock::now();
  Problem problem(model, metric);
  const ParamTable& table = problem.table();
  const size_t n = problem.vars().size();
  if (n == 0 && !problem.has_linear())
    throw InputError("model '" + std::string(model.name()) + "'", "has no free parameter to fit");
  const std::vector<size_t> strides = levels(problem.sample_count(), options.coarse_to_fine);

  std::mt19937_64 rng(options.seed);
  FitResult best;
  double best_cost = std::numeric_limits<double>::infinity();
  int total_iterations = 0;
  for (int start = 0; start < options.starts; ++start) {
    ParamValues pv = ParamValues::defaults(table);
    if (start > 0)
      for (const Var& v : problem.vars()) {
        const double x = draw(table[size_t(v.param)], rng);
        for (int c = 0; c < 3; ++c)
          if (v.channel < 0 || v.channel == c) pv.values[size_t(c)][size_t(v.param)] = x;
      }
    problem.set_stride(strides.front());
    problem.start_colours(pv);  // a transformed residual's colours fitted to the start's shape
    problem.set_base(pv);
    std::vector<double> x(n);
    problem.from_values(pv, x.data());
    if (start == 0 && options.scan_start && n > 0) {  // start 0: the best point of a scan (fit/start_scan.h)
      std::vector<int> var_param;
      for (const Var& v : problem.vars()) var_param.push_back(v.param);
      problem.set_stride(scan_stride(problem.sample_count()));
      const StartScan scan = scan_start(table, var_param, x, [&](const std::vector<double>& p) {
        Objective o;
        return problem.evaluate(p.data(), false, o) ? o.cost : std::numeric_limits<double>::infinity();
      });
      x = scan.x;
      best.scan_points = scan.points;
    }
    bool converged = true, usable = true;
    std::string message = "colours only: solved directly";
    for (size_t level = 0; level < strides.size() && n > 0 && usable; ++level) {
      const bool last = level + 1 == strides.size();
      problem.set_stride(strides[level]);
      ceres::Problem::Options popt;
      popt.cost_function_ownership = ceres::TAKE_OWNERSHIP;
      ceres::Problem cp(popt);
      cp.AddResidualBlock(new CompressedCost(problem), nullptr, x.data());
      for (size_t v = 0; v < n; ++v) {
        const ParamSpec& s = table[size_t(problem.vars()[v].param)];
        cp.SetParameterLowerBound(x.data(), int(v), s.lower);
        cp.SetParameterUpperBound(x.data(), int(v), s.upper);
      }
      ceres::Solver::Options so;
      so.linear_solver_type = ceres::DENSE_QR;
      so.max_num_iterations = options.max_iterations;
      // Coarse levels only bring the start close; the last one converges tightly.
      so.function_tolerance = last ? 1e-12 : 1e-8;
      so.gradient_tolerance = last ? 1e-14 : 1e-10;
      so.parameter_tolerance = last ? 1e-10 : 1e-6;
      so.logging_type = ceres::SILENT;
      so.num_threads = 1;  // the cost function is parallel inside
      StallStop stall;
      so.callbacks.push_back(&stall);
      ceres::Solver::Summary summary;
      ceres::Solve(so, &cp, &summary);
      total_iterations += int(summary.iterations.size()) - 1;
      usable = summary.IsSolutionUsable();
      if (last) {
        converged = summary.termination_type == ceres::CONVERGENCE || stall.stalled();
        message = stall.stalled() ? fmt::format("Stalled: the last {} steps lowered the cost by < {:g} relative.",
                                                StallStop::kWindow, StallStop::kRelative)
                                  : summary.message;
      } else if (usable && !problem.best_point().empty()) {
        // Ceres evaluates a step before its parameter tolerance discards it: the next level starts
        // from the lowest cost this one saw (on exact data one level sooner at the optimum).
        x = problem.best_point();
      }
    }
    if (!usable) continue;
    problem.set_stride(1);
    Objective o;
    if (!problem.evaluate(x.data(), false, o, &pv)) continue;
    bool finite = std::isfinite(o.cost);
    for (const auto& ch : pv.values)
      for (double v : ch) finite = finite && std::isfinite(v);
    if (finite && o.cost < best_cost) {
      best_cost = o.cost;
      best.metric_value = metric.finish(o.cost);
      best.values = pv;
      best.best_start = start;
      best.converged = converged;
      best.message = message;
    }
  }
  if (!std::isfinite(best_cost))
    throw FitError("no start of " + std::to_string(options.starts) + " gave a finite fit of model '" +
                   std::string(model.name()) + "' under metric '" + std::string(metric.id()) + "'");
  best.iterations = total_iterations;
  best.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // metric_value: the fitting metric at the result, summed by the fit itself over the same
  // domain (Metric::value sums in another order: equal to round-off).
  return best;
}

}  // namespace brdfkit::fit
