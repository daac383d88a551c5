#include "brdfkit/fit/engine/projected_objective.h"

#include <tbb/parallel_for.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "brdfkit/core/ordered_reduce.h"
#include "brdfkit/fit/engine/box_least_squares.h"
#include "brdfkit/fit/engine/finite_difference.h"
#include "brdfkit/fit/engine/weighted_dots.h"

namespace brdfkit::fit {

namespace {

using Eigen::Index;

// Inner products of one block gathered, then computed in one weighted_dots sweep into their slots.
class DotBatch {
 public:
  void add(const double* x, const double* y, double* slot) {
    terms_.push_back({x, y});
    slots_.push_back(slot);
  }
  void run(const SampleBlock& b) {
    values_.resize(terms_.size());
    weighted_dots(b.n, b.w2.data(), terms_, values_.data());
    for (size_t t = 0; t < slots_.size(); ++t) *slots_[t] = values_[t];
  }

 private:
  std::vector<DotTerm> terms_;
  std::vector<double*> slots_;
  std::vector<double> values_;
};

double weighted_dot(const SampleBlock& b, const double* x, const double* y) {
  return fit::weighted_dot(b.n, b.w2.data(), x, y);
}

}  // namespace

ProjectedObjective::ProjectedObjective(const FitContext& ctx, std::vector<LinearBasis> bases)
    : ctx_(ctx), paired_(dynamic_cast<const PairedEvaluation*>(&ctx.model)), bases_(std::move(bases)) {
  // One basis set for R, G and B when no variable is per channel and the model ignores the channel.
  bool channel_free = std::none_of(ctx.vars.begin(), ctx.vars.end(), [](const SolverVariable& v) { return v.channel >= 0; });
  if (channel_free) {
    std::vector<double> p = ParamValues::defaults(ctx.model.params()).values[0];
    for (const LinearBasis& b : bases_) p[size_t(b.lin)] = 1.0;
    channel_free = same_in_every_channel(ctx.model, p);
  }
  classes_ = channel_free ? 1 : 3;
  for (size_t j = 0; j < bases_.size(); ++j) {
    constant_.push_back(basis_independent_of_shape(ctx.model, ctx.vars, bases_, j, classes_));
    if (!constant_.back()) varying_.push_back(j);
  }
}

void ProjectedObjective::reset(bool new_blocks) {
  current_.valid = false;
  if (new_blocks) fill_constant_bases();
}

// Evaluates the bases `js` of class q at the shape of pv on block b into out(j). A Fresnel-like
// pair (the bases at P_lo and P_hi, adjacent in bases_) takes one pass where the model offers it
// (models/paired_evaluation.h): Cook-Torrance computes D and G once for both (DESIGN.md §12).
template <class Out>
void ProjectedObjective::eval_bases(const ParamValues& pv, int q, const SampleBlock& b, const std::vector<size_t>& js,
                                    Out&& out) const {
  for (size_t a = 0; a < js.size(); ++a) {
    const size_t j = js[a];
    const std::vector<double> p = basis_params(pv, q, bases_, j);
    const LinearBasis& bj = bases_[j];
    const bool pair = bj.affine >= 0 && a + 1 < js.size() && js[a + 1] == j + 1 && bases_[j + 1].lin == bj.lin &&
                      bases_[j + 1].affine == bj.affine;
    if (pair && paired_ &&
        paired_->eval_batch_pair(p.data(), q, bj.affine, bj.affine_value, bases_[j + 1].affine_value, b.n, b.d, out(j),
                                out(j + 1))) {
      ++a;
      continue;
    }
    ctx_.model.eval_batch(p.data(), q, b.n, b.d, out(j));
  }
}

// eval_bases for every class into out(q, j): with three classes and no Fresnel-like pair among
// the bases, one Model::eval_batch_rgb per basis (He computes its shape terms once for R, G and B).
template <class Out>
void ProjectedObjective::eval_bases_all(const ParamValues& pv, const SampleBlock& b, const std::vector<size_t>& js,
                                        Out&& out) const {
  const bool paired = std::any_of(js.begin(), js.end(), [&](size_t j) { return bases_[j].affine >= 0; });
  if (classes_ == 1 || paired) {
    for (int q = 0; q < classes_; ++q) eval_bases(pv, q, b, js, [&](size_t j) { return out(size_t(q), j); });
    return;
  }
  for (size_t j : js) {
    const std::array<std::vector<double>, 3> p = {basis_params(pv, 0, bases_, j), basis_params(pv, 1, bases_, j),
                                                  basis_params(pv, 2, bases_, j)};
    const double* const pp[3] = {p[0].data(), p[1].data(), p[2].data()};
    double* const o[3] = {out(0, j), out(1, j), out(2, j)};
    ctx_.model.eval_batch_rgb(pp, b.n, b.d, o);
  }
}

void ProjectedObjective::fill_constant_bases() {
  const size_t K = bases_.size();
  const ParamValues pv = ParamValues::defaults(ctx_.model.params());
  std::vector<size_t> js;
  for (size_t j = 0; j < K; ++j)
    if (constant_[j]) js.push_back(j);
  constant_bases_.assign(ctx_.blocks.size(), {});
  tbb::parallel_for(size_t(0), ctx_.blocks.size(), [&](size_t i) {
    const SampleBlock& b = ctx_.blocks[i];
    auto& store = constant_bases_[i];
    store.assign(classes() * K, {});
    eval_bases_all(pv, b, js, [&](size_t q, size_t j) {
      auto& v = store[q * K + j];
      v.resize(b.n);
      return v.data();
    });
    // A class equal to class 0 (Lambert's 1/π in every channel) is kept once: empty, read as class 0.
    for (size_t q = 1; q < classes(); ++q)
      for (size_t j : js)
        if (store[q * K + j] == store[j]) std::vector<double>().swap(store[q * K + j]);
  });
}

// Basis j of class q in block i at the shape of current_.
const double* ProjectedObjective::basis(size_t i, int q, size_t j) const {
  const size_t K = bases_.size();
  if (!constant_[j]) return current_.bases[i][size_t(q) * K + j].data();
  const std::vector<double>& v = constant_bases_[i][size_t(q) * K + j];
  return (v.empty() ? constant_bases_[i][j] : v).data();
}

// Block i's varying bases at pv into current_, and its share of <B,B> (upper triangle) and <B,m_c>.
void ProjectedObjective::gram_partials(size_t i, const ParamValues& pv, double* acc) {
  const size_t K = bases_.size(), Q = classes();
  const SampleBlock& b = ctx_.blocks[i];
  current_.bases[i].assign(Q * K, {});
  eval_bases_all(pv, b, varying_, [&](size_t q, size_t j) {
    auto& v = current_.bases[i][q * K + j];
    v.resize(b.n);
    return v.data();
  });
  DotBatch dots;
  for (size_t q = 0; q < Q; ++q) {
    double* G = acc + q * (K * K + 3 * K);
    double* y = G + K * K;  // y[c·K + j] = <b_j, m_c>
    for (size_t j = 0; j < K; ++j) {
      const double* bj = basis(i, int(q), j);
      for (size_t l = j; l < K; ++l) dots.add(bj, basis(i, int(q), l), &G[j * K + l]);
      for (size_t c = 0; c < 3; ++c)
        if (Q == 1 || c == q) dots.add(bj, b.m[c], &y[c * K + j]);
    }
  }
  dots.run(b);
}

// The bases at x and their Gram matrices, kept for the last point only: Ceres asks for derivatives
// at the trial point it has just evaluated and accepted. Any other point is swept again, which is
// cheaper than holding a second basis set through every fit (on the 1° grid, 18 MB for GGX and 28 MB
// for He's three colour classes, heaptrack).
void ProjectedObjective::update_gram(const double* x, const ParamValues& pv) {
  const size_t nv = ctx_.vars.size();
  if (current_.valid && std::equal(current_.x.begin(), current_.x.end(), x)) return;
  const size_t K = bases_.size(), Q = classes(), width = K * K + 3 * K;
  current_.bases.assign(ctx_.blocks.size(), {});
  const std::vector<double> sums =
      ordered_reduce(ctx_.blocks.size(), Q * width, [&](size_t i, double* acc) { gram_partials(i, pv, acc); });
  current_.gram.assign(Q, Eigen::MatrixXd::Zero(Index(K), Index(K)));
  for (auto& y : current_.ym) y = Eigen::VectorXd::Zero(Index(K));
  for (size_t q = 0; q < Q; ++q) {
    const double* G = sums.data() + q * width;
    for (size_t j = 0; j < K; ++j)
      for (size_t l = j; l < K; ++l) current_.gram[q](Index(j), Index(l)) = G[j * K + l];
    for (size_t c = 0; c < 3; ++c)
      if (Q == 1 || c == q)
        for (size_t j = 0; j < K; ++j) current_.ym[c][Index(j)] = G[K * K + c * K + j];
    current_.gram[q] = current_.gram[q].selfadjointView<Eigen::Upper>();
  }
  current_.x.assign(x, x + nv);
  current_.valid = true;
}

// β per channel: the box-constrained least-squares colours. A paired basis carries u or v ≥ 0;
// its colour L = u + v is bounded below by 0 (linear_structure.h).
bool ProjectedObjective::solve_colours(std::array<Eigen::VectorXd, 3>& beta, Eigen::VectorXd& lo,
                                       Eigen::VectorXd& hi) const {
  const size_t K = bases_.size();
  lo = Eigen::VectorXd::Zero(Index(K));
  hi = Eigen::VectorXd::Zero(Index(K));
  for (size_t j = 0; j < K; ++j) {
    const ParamSpec& s = ctx_.model.params()[size_t(bases_[j].lin)];
    lo[Index(j)] = bases_[j].affine >= 0 ? 0.0 : s.lower;
    hi[Index(j)] = bases_[j].affine >= 0 ? std::numeric_limits<double>::infinity() : s.upper;
  }
  for (int c = 0; c < 3; ++c) {
    const Eigen::MatrixXd& G = current_.gram[classes_ == 1 ? 0 : size_t(c)];
    if (!G.allFinite() || !current_.ym[size_t(c)].allFinite()) return false;
    beta[size_t(c)] = box_least_squares(G, current_.ym[size_t(c)], lo, hi);
  }
  return true;
}

// β (per channel, per basis) → parameter values: a colour directly, a pair (v, u) as L = u + v,
// P = P_lo + (P_hi − P_lo) u/(u + v).
void ProjectedObjective::write_colours(const std::array<Eigen::VectorXd, 3>& beta, ParamValues& pv) const {
  const ParamTable& table = ctx_.model.params();
  for (int c = 0; c < 3; ++c) {
    auto& v = pv.values[size_t(c)];
    for (size_t j = 0; j < bases_.size(); ++j) {
      const LinearBasis& b = bases_[j];
      if (b.affine < 0) {
        v[size_t(b.lin)] = beta[size_t(c)][Index(j)];
      } else if (b.affine_value == table[size_t(b.affine)].lower) {  // the pair (v, u) starts here
        const double lo_coef = beta[size_t(c)][Index(j)], hi_coef = beta[size_t(c)][Index(j + 1)];
        const ParamSpec& L = table[size_t(b.lin)];
        const ParamSpec& P = table[size_t(b.affine)];
        const double sum = lo_coef + hi_coef;
        // L above its upper bound is clamped (a limitation of the pairing).
        v[size_t(b.lin)] = std::min(sum, L.upper);
        if (sum > 0) v[size_t(b.affine)] = P.lower + (P.upper - P.lower) * hi_coef / sum;
      }
    }
  }
}

ProjectedObjective::Extended ProjectedObjective::extended(bool derivatives) const {
  const size_t K = bases_.size(), nv = ctx_.vars.size(), Q = classes();
  Extended e;
  e.ext.resize(Q);
  if (derivatives)
    for (size_t q = 0; q < Q; ++q)
      for (size_t v = 0; v < nv; ++v)
        if (ctx_.vars[v].affects(int(q)))
          for (size_t j : varying_) e.ext[q].push_back({v, j});
  e.L.resize(Q);
  e.offset.assign(Q + 1, 0);
  for (size_t q = 0; q < Q; ++q) {
    e.L[q] = K + e.ext[q].size();
    e.offset[q + 1] = e.offset[q] + e.L[q] * e.L[q] + 3 * e.L[q];
  }
  e.width = 1 + nv + e.offset[Q];
  return e;
}

// The varying bases of class q in block i at the shape of pv, from their values at x (at_x)
// where the model rescales them without its costly terms (Model::eval_batch_from): false where it
// cannot, and then out is to be filled by eval_bases.
template <class Out>
bool ProjectedObjective::rescale_bases(const ParamValues& at_x, const ParamValues& pv, int q, size_t i,
                                       Out&& out) const {
  const SampleBlock& b = ctx_.blocks[i];
  for (size_t j : varying_) {
    const std::vector<double> p = basis_params(pv, q, bases_, j), p0 = basis_params(at_x, q, bases_, j);
    if (!ctx_.model.eval_batch_from(p.data(), p0.data(), basis(i, q, j), q, b.n, b.d, out(j))) return false;
  }
  return true;
}

// d_vj = (b_j(x + h_v e_v) − b_j(x)) / h_v in block i, for every class q and variable v moving it.
ProjectedObjective::Derivatives ProjectedObjective::derivative_bases(size_t i, const ParamValues& at_x,
                                                                     const std::vector<ParamValues>& shifted,
                                                                     const std::vector<double>& h) const {
  const size_t K = bases_.size(), nv = ctx_.vars.size(), Q = classes();
  const SampleBlock& b = ctx_.blocks[i];
  Derivatives dv(Q * nv * K);
  const auto slot = [&](size_t q, size_t v, size_t j) {
    auto& d = dv[(q * nv + v) * K + j];
    d.resize(b.n);
    return d.data();
  };
  for (size_t v = 0; v < nv; ++v) {
    if (ctx_.vars[v].channel < 0) {  // moves every class
      eval_bases_all(shifted[v], b, varying_, [&](size_t q, size_t j) { return slot(q, v, j); });
      continue;
    }
    const int q = ctx_.vars[v].channel;  // a per-channel variable implies three classes
    const auto out = [&](size_t j) { return slot(size_t(q), v, j); };
    if (!rescale_bases(at_x, shifted[v], q, i, out)) eval_bases(shifted[v], q, b, varying_, out);
  }
  for (size_t q = 0; q < Q; ++q)
    for (size_t v = 0; v < nv; ++v) {
      if (!ctx_.vars[v].affects(int(q))) continue;
      const double inv = 1.0 / h[v];
      for (size_t j : varying_) {
        double* d = dv[(q * nv + v) * K + j].data();
        const double* b0 = basis(i, int(q), j);
        for (size_t k = 0; k < b.n; ++k) d[k] = (d[k] - b0[k]) * inv;
      }
    }
  return dv;
}

// Block i's cost Σ w² r² (acc[0]) and Σ w² r (d_v β), Jᵀr without the ∂β term (acc[1 + v]).
void ProjectedObjective::residual_partials(size_t i, const std::array<Eigen::VectorXd, 3>& beta,
                                           const Derivatives& dv, bool derivatives, double* acc) const {
  const size_t K = bases_.size(), nv = ctx_.vars.size(), Q = classes();
  const SampleBlock& b = ctx_.blocks[i];
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
    acc[0] += weighted_dot(b, r.data(), r.data());
    if (!derivatives) continue;
    for (size_t v = 0; v < nv; ++v) {
      if (!ctx_.vars[v].affects(int(q))) continue;
      std::fill(g.begin(), g.end(), 0.0);
      for (size_t j : varying_) {
        const double* d = dv[(q * nv + v) * K + j].data();
        const double coef = bc[Index(j)];
        for (size_t k = 0; k < b.n; ++k) g[k] += coef * d[k];
      }
      acc[1 + v] += weighted_dot(b, r.data(), g.data());
    }
  }
}

// Block i's share of the extended Gram matrices E[q] = <e_a, e_b> (the bases' own block excepted:
// it is in current_.gram) and of <e_a, m_c> for the derivative vectors.
void ProjectedObjective::extended_partials(size_t i, const Extended& e, const Derivatives& dv, double* acc) const {
  const size_t K = bases_.size(), nv = ctx_.vars.size();
  const SampleBlock& b = ctx_.blocks[i];
  DotBatch dots;
  for (size_t q = 0; q < classes(); ++q) {
    const size_t L = e.L[q];
    std::vector<const double*> col(L);
    for (size_t j = 0; j < K; ++j) col[j] = basis(i, int(q), j);
    for (size_t a = 0; a < e.ext[q].size(); ++a) col[K + a] = dv[(q * nv + e.ext[q][a].first) * K + e.ext[q][a].second].data();
    double* G = acc + 1 + nv + e.offset[q];
    double* y = G + L * L;
    for (size_t a = 0; a < L; ++a) {
      for (size_t bb = std::max(a, K); bb < L; ++bb) dots.add(col[a], col[bb], &G[a * L + bb]);
      if (a < K) continue;
      for (size_t c = 0; c < 3; ++c)
        if (classes_ == 1 || c == q) dots.add(col[a], b.m[c], &y[c * L + a]);
    }
  }
  dots.run(b);
}

// Channel c's Gauss-Newton terms (Golub-Pereyra): J_v = d_v β + B ∂β_v, from the Gram blocks.
void ProjectedObjective::add_channel_jacobian(int c, const Eigen::VectorXd& bc, const Eigen::VectorXd& lo,
                                              const Eigen::VectorXd& hi, const Extended& e,
                                              const std::vector<Eigen::MatrixXd>& E,
                                              const std::vector<std::array<Eigen::VectorXd, 3>>& Ey,
                                              ObjectiveValue& out) const {
  const size_t K = bases_.size(), nv = ctx_.vars.size();
  const size_t q = classes_ == 1 ? 0 : size_t(c), L = e.L[q];
  const Eigen::MatrixXd& G = current_.gram[q];
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
    for (size_t a = 0; a < e.ext[q].size(); ++a)
      if (e.ext[q][a].first == v && e.ext[q][a].second == j) return Index(K + a);
    return -1;
  };
  std::vector<size_t> vs;
  std::vector<Eigen::VectorXd> gv, dbeta;  // d_v β over E's columns; ∂β_v over the bases
  for (size_t v = 0; v < nv; ++v) {
    if (!ctx_.vars[v].affects(int(q))) continue;
    vs.push_back(v);
    Eigen::VectorXd coef = Eigen::VectorXd::Zero(Index(L));
    for (size_t j : varying_) coef[at(v, j)] = bc[Index(j)];
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(Index(K));  // ∂y − ∂G β, ∂G = <d_v, B> + <B, d_v>
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
  const Eigen::MatrixXd EB = E[q].leftCols(Index(K));                     // <e_a, b_l>
  const Eigen::VectorXd resid_grad = G * bc - current_.ym[size_t(c)];  // <B, r>: 0 on the free colours
  for (size_t a = 0; a < vs.size(); ++a) {
    out.gradient[Index(vs[a])] += dbeta[a].dot(resid_grad);
    for (size_t bb = 0; bb < vs.size(); ++bb)
      out.jtj(Index(vs[a]), Index(vs[bb])) += gv[a].dot(E[q] * gv[bb]) + gv[a].dot(EB * dbeta[bb]) +
                                               gv[bb].dot(EB * dbeta[a]) + dbeta[a].dot(G * dbeta[bb]);
  }
}

bool ProjectedObjective::evaluate(const double* x, bool derivatives, ObjectiveValue& out, ParamValues& values) {
  const size_t nv = ctx_.vars.size(), Q = classes();
  values = ctx_.values_at(x);
  update_gram(x, values);
  std::array<Eigen::VectorXd, 3> beta;
  Eigen::VectorXd lo, hi;
  if (!solve_colours(beta, lo, hi)) return false;
  const ParamValues at_x = values;  // before the colours are written: the bases' parameters at x
  write_colours(beta, values);
  const Extended e = extended(derivatives);
  std::vector<double> h;
  const std::vector<ParamValues> shifted =
      derivatives ? shifted_points(ctx_.vars, x, ctx_.base, h) : std::vector<ParamValues>{};
  const std::vector<double> sums = ordered_reduce(ctx_.blocks.size(), e.width, [&](size_t i, double* acc) {
    const Derivatives dv = derivatives ? derivative_bases(i, at_x, shifted, h) : Derivatives{};
    residual_partials(i, beta, dv, derivatives, acc);
    if (derivatives) extended_partials(i, e, dv, acc);
  });
  out.cost = sums[0];
  out.gradient = Eigen::VectorXd::Zero(Index(nv));
  out.jtj = Eigen::MatrixXd::Zero(Index(nv), Index(nv));
  if (!derivatives) return true;
  for (size_t v = 0; v < nv; ++v) out.gradient[Index(v)] = sums[1 + v];
  std::vector<Eigen::MatrixXd> E(Q);
  std::vector<std::array<Eigen::VectorXd, 3>> Ey(Q);
  for (size_t q = 0; q < Q; ++q) {
    const size_t L = e.L[q];
    const double* G = sums.data() + 1 + nv + e.offset[q];
    E[q] = Eigen::MatrixXd::Zero(Index(L), Index(L));
    for (auto& y : Ey[q]) y = Eigen::VectorXd::Zero(Index(L));
    for (size_t a = 0; a < L; ++a) {
      for (size_t bb = a; bb < L; ++bb) E[q](Index(a), Index(bb)) = G[a * L + bb];
      for (size_t c = 0; c < 3; ++c) Ey[q][c][Index(a)] = G[L * L + c * L + a];
    }
    E[q].topLeftCorner(Index(bases_.size()), Index(bases_.size())) = current_.gram[q];
    E[q] = E[q].selfadjointView<Eigen::Upper>();
  }
  for (int c = 0; c < 3; ++c) add_channel_jacobian(c, beta[size_t(c)], lo, hi, e, E, Ey, out);
  return true;
}

}  // namespace brdfkit::fit
