#include "brdfkit/fit/engine/log_residual_objective.h"

#include <tbb/parallel_for.h>

#include <Eigen/Dense>
#include <algorithm>

#include "brdfkit/core/ordered_reduce.h"
#include "brdfkit/fit/engine/box_least_squares.h"
#include "brdfkit/fit/engine/finite_difference.h"

namespace brdfkit::fit {

using Eigen::Index;

LogResidualObjective::LogResidualObjective(const FitContext& ctx, const std::vector<int>& colours) : ctx_(ctx) {
  const ParamTable& table = ctx.model.params();
  std::vector<int> colour_of(table.size(), -1);
  for (size_t j = 0; j < colours.size(); ++j) {
    colour_of[size_t(colours[j])] = int(j);
    bases_.push_back({colours[j]});
  }
  for (auto& v : var_of_) v.assign(colours.size(), -1);
  for (size_t v = 0; v < ctx.vars.size(); ++v) {
    const int j = colour_of[size_t(ctx.vars[v].param)];
    if (j >= 0) var_of_[size_t(ctx.vars[v].channel)][size_t(j)] = int(v);  // colours are per channel
    else shape_.push_back(v);
  }
  // One basis set for R, G, B when no shape variable is per channel and the model ignores the
  // channel (probed here; classes_at also compares the channels' parameters).
  channel_free_ = std::all_of(shape_.begin(), shape_.end(), [&](size_t v) { return ctx.vars[v].channel < 0; });
  const ParamValues pv = ParamValues::defaults(table);
  for (size_t j = 0; j < bases_.size() && channel_free_; ++j)
    channel_free_ = same_in_every_channel(ctx.model, basis_at(pv, 0, j));
  for (size_t j = 0; j < bases_.size(); ++j) constant_.push_back(basis_independent_of_shape(ctx.model, ctx.vars, bases_, j, 3));
}

void LogResidualObjective::reset(bool new_blocks) {
  if (!new_blocks) return;  // the bases are keyed by their parameters, the base does not matter
  const size_t K = bases_.size(), nb = ctx_.blocks.size();
  keys_.assign(3 * K, {});
  values_.assign(nb, std::vector<std::vector<double>>(3 * K));
  tm_.assign(nb, {});
  tbb::parallel_for(size_t(0), nb, [&](size_t i) {
    const SampleBlock& b = ctx_.blocks[i];
    tm_[i].resize(3 * b.n);
    for (int c = 0; c < 3; ++c)
      for (size_t k = 0; k < b.n; ++k)
        tm_[i][size_t(c) * b.n + k] = transformed_measured(ctx_.transform, b.f[k], b.m[c][k]);
  });
}

// Basis classes at pv: 1 when R, G, B share one basis set, else 3.
size_t LogResidualObjective::classes_at(const ParamValues& pv) const {
  if (!channel_free_) return 3;
  for (size_t j = 0; j < bases_.size(); ++j)
    for (int c = 1; c < 3; ++c)
      if (basis_at(pv, c, j) != basis_at(pv, 0, j)) return 3;
  return 1;
}

// Makes values_ hold every basis at pv's shape (constant bases at the table's default shape, so
// once per stride).
void LogResidualObjective::prepare_bases(const ParamValues& pv, size_t Q) {
  const size_t K = bases_.size();
  const ParamValues defaults = ParamValues::defaults(ctx_.model.params());
  std::vector<std::pair<size_t, std::vector<double>>> todo;  // (q·K + j, parameters)
  for (size_t q = 0; q < Q; ++q)
    for (size_t j = 0; j < K; ++j) {
      std::vector<double> p = basis_at(pv, int(q), j);
      if (constant_[j])  // the shape variables at their defaults: one key per stride
        for (size_t v : shape_) p[size_t(ctx_.vars[v].param)] = defaults.values[q][size_t(ctx_.vars[v].param)];
      if (keys_[q * K + j] != p) todo.push_back({q * K + j, std::move(p)});
    }
  if (todo.empty()) return;
  tbb::parallel_for(size_t(0), ctx_.blocks.size(), [&](size_t i) {
    const SampleBlock& b = ctx_.blocks[i];
    for (const auto& [qj, p] : todo) {
      auto& v = values_[i][qj];
      v.resize(b.n);
      ctx_.model.eval_batch(p.data(), int(qj / K), b.n, b.d, v.data());
    }
  });
  for (auto& [qj, p] : todo) keys_[qj] = std::move(p);
}

// Block i's partial sums, per channel c at partial + c·(1 + M + M²): cost, the gradient over
// channel c's columns (its K colours, then the shape variables that affect it), their JᵀJ.
void LogResidualObjective::block_partials(size_t i, size_t Q, const std::vector<ParamValues>& shifted,
                                          const std::vector<double>& h, const std::array<std::vector<double>, 3>& beta,
                                          const std::array<std::vector<int>, 3>& cols,
                                          const std::array<std::vector<size_t>, 3>& shape_of, bool derivatives,
                                          double* partial) const {
  const size_t K = bases_.size(), S = shape_.size(), M = K + S;
  const SampleBlock& b = ctx_.blocks[i];
  // ∂b_j/∂s of each class by forward differences (constant bases have none).
  std::vector<std::vector<double>> d(derivatives ? Q * S * K : 0);  // [(q·S + s)·K + j]
  for (size_t q = 0; q < Q && derivatives; ++q)
    for (size_t s = 0; s < S; ++s) {
      const size_t v = shape_[s];
      if (!ctx_.vars[v].affects(int(q))) continue;
      const double inv = 1.0 / h[v];
      for (size_t j = 0; j < K; ++j) {
        if (constant_[j]) continue;
        auto& dj = d[(q * S + s) * K + j];
        dj.resize(b.n);
        const std::vector<double> p = basis_at(shifted[v], int(q), j);
        ctx_.model.eval_batch(p.data(), int(q), b.n, b.d, dj.data());
        const double* b0 = values_[i][q * K + j].data();
        for (size_t k = 0; k < b.n; ++k) dj[k] = (dj[k] - b0[k]) * inv;
      }
    }
  std::vector<double> a(M);
  for (int c = 0; c < 3; ++c) {
    const size_t q = Q == 1 ? 0 : size_t(c);
    double* acc = partial + size_t(c) * (1 + M + M * M);
    double* grad = acc + 1;
    double* jtj = grad + M;
    const size_t mc = cols[size_t(c)].size();
    const double* tm = tm_[i].data() + size_t(c) * b.n;
    std::vector<const double*> bj(K);
    for (size_t j = 0; j < K; ++j) bj[j] = values_[i][q * K + j].data();
    const std::vector<double>& bc = beta[size_t(c)];
    double cost = 0;
    for (size_t k = 0; k < b.n; ++k) {
      double rho = 0;
      for (size_t j = 0; j < K; ++j) rho += bc[j] * bj[j][k];
      const double r = metric_residual(ctx_.transform, b.rw[k], b.f[k], rho, tm[k]);
      cost += r * r;
      if (!derivatives) continue;
      const double slope = b.rw[k] * b.f[k] * transform_slope(ctx_.transform, b.f[k] * rho);
      for (size_t j = 0; j < K; ++j) a[j] = slope * bj[j][k];
      for (size_t m = K; m < mc; ++m) {
        const size_t s = shape_of[size_t(c)][m - K];
        double drho = 0;
        for (size_t j = 0; j < K; ++j)
          if (!constant_[j]) drho += bc[j] * d[(q * S + s) * K + j][k];
        a[m] = slope * drho;
      }
      for (size_t m = 0; m < mc; ++m) {
        grad[m] += a[m] * r;
        for (size_t l = m; l < mc; ++l) jtj[m * M + l] += a[m] * a[l];
      }
    }
    acc[0] = cost;
  }
}

bool LogResidualObjective::evaluate(const double* x, bool derivatives, ObjectiveValue& out, ParamValues& values) {
  const size_t K = bases_.size(), nv = ctx_.vars.size(), S = shape_.size(), M = K + S;
  values = ctx_.values_at(x);
  const size_t Q = classes_at(values);
  prepare_bases(values, Q);
  std::vector<double> h;
  const std::vector<ParamValues> shifted =
      derivatives ? shifted_points(ctx_.vars, x, ctx_.base, h) : std::vector<ParamValues>{};
  std::array<std::vector<int>, 3> cols;  // channel c's columns: its K colours, then its shape variables
  std::array<std::vector<size_t>, 3> shape_of;  // indices into shape_
  std::array<std::vector<double>, 3> beta;
  for (int c = 0; c < 3; ++c) {
    cols[size_t(c)] = var_of_[size_t(c)];
    for (size_t s = 0; s < S; ++s)
      if (ctx_.vars[shape_[s]].affects(c)) {
        cols[size_t(c)].push_back(int(shape_[s]));
        shape_of[size_t(c)].push_back(s);
      }
    for (size_t j = 0; j < K; ++j) beta[size_t(c)].push_back(values.values[size_t(c)][size_t(bases_[j].lin)]);
  }
  const size_t width = 1 + M + M * M;
  const std::vector<double> sums = ordered_reduce(ctx_.blocks.size(), 3 * width, [&](size_t i, double* partial) {
    block_partials(i, Q, shifted, h, beta, cols, shape_of, derivatives, partial);
  });
  out.cost = 0;
  out.gradient = Eigen::VectorXd::Zero(Index(nv));
  out.jtj = Eigen::MatrixXd::Zero(Index(nv), Index(nv));
  for (size_t c = 0; c < 3; ++c) {
    const double* acc = sums.data() + c * width;
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

void LogResidualObjective::start_colours(ParamValues& pv) {
  const size_t K = bases_.size();
  const size_t Q = classes_at(pv);
  prepare_bases(pv, Q);
  const size_t width = K * K + K;
  const std::vector<double> sums = ordered_reduce(ctx_.blocks.size(), 3 * width, [&](size_t i, double* partial) {
    const SampleBlock& b = ctx_.blocks[i];
    for (int c = 0; c < 3; ++c) {
      const size_t q = Q == 1 ? 0 : size_t(c);
      double* G = partial + size_t(c) * width;
      for (size_t k = 0; k < b.n; ++k) {
        const double fm = b.f[k] * b.m[c][k];
        const double w = b.rw[k] * b.f[k] * transform_slope(ctx_.transform, std::max(fm, 0.0));
        const double w2 = w * w;
        for (size_t j = 0; j < K; ++j) {
          const double bj = values_[i][q * K + j][k];
          for (size_t l = j; l < K; ++l) G[j * K + l] += w2 * bj * values_[i][q * K + l][k];
          G[K * K + j] += w2 * bj * b.m[c][k];
        }
      }
    }
  });
  const ParamTable& table = ctx_.model.params();
  for (int c = 0; c < 3; ++c) {
    const double* g = sums.data() + size_t(c) * width;
    Eigen::MatrixXd G = Eigen::MatrixXd::Zero(Index(K), Index(K));
    Eigen::VectorXd y = Eigen::VectorXd::Zero(Index(K)), lo = y, hi = y;
    for (size_t j = 0; j < K; ++j) {
      for (size_t l = j; l < K; ++l) G(Index(j), Index(l)) = g[j * K + l];
      y[Index(j)] = g[K * K + j];
      lo[Index(j)] = table[size_t(bases_[j].lin)].lower;
      hi[Index(j)] = table[size_t(bases_[j].lin)].upper;
    }
    G = G.selfadjointView<Eigen::Upper>();
    if (!G.allFinite() || !y.allFinite()) return;
    const Eigen::VectorXd b = box_least_squares(G, y, lo, hi);
    for (size_t j = 0; j < K; ++j) pv.values[size_t(c)][size_t(bases_[j].lin)] = b[Index(j)];
  }
}

}  // namespace brdfkit::fit
