#include "brdfkit/fit/variable_projection.h"

#include <ceres/ceres.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>

#include "brdfkit/core/error.h"
#include "brdfkit/fit/box_least_squares.h"
#include "brdfkit/fit/model_batch.h"

namespace brdfkit::fit {

namespace {

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

// The fitting problem on a metric's cached domain: parameter layout, the colour projection and
// the residual vector r(k, c) of metric.h, stored channel-major (c·N + sample).
//
// Variable projection (seed 002 §3) solves the per-channel linear parameters (kd, ks) for fixed
// shape. A per-channel parameter P on which ρ depends affinely and only through one linear
// parameter L (Schlick's F0 under ks: ks F = ks F0 + ks (1 − F0)(1 − cosθd)⁵) joins the linear
// sub-problem too (DESIGN.md §12: kd, ks·F0, ks·(1 − F0) are the linear colours): L b(P) =
// u b(P_hi) + v b(P_lo) with u = L t, v = L (1 − t), t = (P − P_lo)/(P_hi − P_lo), u, v ≥ 0; so
// L = u + v and P = P_lo + (P_hi − P_lo) u/(u + v). Both properties are checked numerically.
class Problem {
 public:
  Problem(const Model& model, const Metric& metric)
      : model_(model), metric_(metric), table_(model.params()), fast_(batch_eval_for(model)) {
    offset_.push_back(0);
    for (size_t i = 0; i < metric.chunk_count(); ++i) offset_.push_back(offset_.back() + chunk(i).size());
    n_ = offset_.back();
    std::vector<int> lin;
    for (size_t p = 0; p < table_.size(); ++p)
      if (table_[p].linear && table_[p].scope == Scope::PerChannel) lin.push_back(int(p));
    project_ = metric.transform() == Transform::Identity && !lin.empty();
    std::vector<int> paired(table_.size(), -1);  // P → L
    if (project_) pair_affine(lin, paired);
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
    if (project_) basis_.assign(size_t(classes_) * bases_.size(), std::vector<double>(n_));
    for (size_t j = 0; j < bases_.size(); ++j) constant_.push_back(shape_independent(j));
  }

  const std::vector<Var>& vars() const { return vars_; }
  size_t residual_count() const { return 3 * n_; }
  const ParamTable& table() const { return table_; }
  bool has_linear() const { return !bases_.empty() || project_; }
  bool projects() const { return project_; }

  void to_values(const double* x, ParamValues& pv) const {
    for (size_t v = 0; v < vars_.size(); ++v)
      for (int c = 0; c < 3; ++c)
        if (vars_[v].channel < 0 || vars_[v].channel == c) pv.values[size_t(c)][size_t(vars_[v].param)] = x[v];
  }
  void from_values(const ParamValues& pv, double* x) const {
    for (size_t v = 0; v < vars_.size(); ++v)
      x[v] = pv.values[size_t(std::max(0, vars_[v].channel))][size_t(vars_[v].param)];
  }

  // Solves the colours for the shape in pv (identity-transform residual), writing them into pv.
  bool project(ParamValues& pv) {
    const size_t K = bases_.size();
    const size_t stride = 3 * (K * K + K);
    std::vector<double> partial(metric_.chunk_count() * stride, 0.0);
    tbb::parallel_for(size_t(0), metric_.chunk_count(), [&](size_t i) {
      const MetricChunk& ch = chunk(i);
      const size_t off = offset_[i];
      const SoaPairs d{ch.wi_x.data(), ch.wi_y.data(), ch.wi_z.data(), ch.wo_x.data(), ch.wo_y.data(), ch.wo_z.data()};
      for (int q = 0; q < classes_; ++q) {
        for (size_t j = 0; j < K; ++j) {
          if (constant_[j] && bases_ready_) continue;  // e.g. the Lambertian 1/π: computed once
          std::vector<double> p = pv.values[size_t(q)];
          for (const Basis& b : bases_) p[size_t(b.lin)] = 0.0;
          p[size_t(bases_[j].lin)] = 1.0;
          if (bases_[j].affine >= 0) p[size_t(bases_[j].affine)] = bases_[j].affine_value;
          eval_pairs(model_, fast_, p.data(), q, ch.size(), d, basis_[size_t(q) * K + j].data() + off);
        }
      }
      // Normal equations of Σ (s f)² (Σ_j β_j b_j − m)² per channel, seed 002 §3.
      std::vector<double> w2(ch.size());
      for (size_t k = 0; k < ch.size(); ++k) {
        const double w = ch.sqrt_weight[k] * ch.factor[k];
        w2[k] = w * w;
      }
      double* acc = partial.data() + i * stride;
      for (int c = 0; c < 3; ++c) {
        const int q = classes_ == 1 ? 0 : c;
        double* A = acc + size_t(c) * (K * K + K);
        double* y = A + K * K;
        const auto& m = ch.measured[size_t(c)];
        for (size_t j = 0; j < K; ++j) {
          const double* bj = basis_[size_t(q) * K + j].data() + off;
          if (c == 0 || classes_ > 1)
            for (size_t l = j; l < K; ++l) {
              const double* bl = basis_[size_t(q) * K + l].data() + off;
              double s = 0;
              for (size_t k = 0; k < ch.size(); ++k) s += w2[k] * bj[k] * bl[k];
              A[j * K + l] = s;
            }
          else
            for (size_t l = j; l < K; ++l) A[j * K + l] = acc[j * K + l];
          double s = 0;
          for (size_t k = 0; k < ch.size(); ++k) s += w2[k] * bj[k] * m[k];
          y[j] = s;
        }
      }
    });
    bases_ready_ = true;
    Eigen::VectorXd lo(K), hi(K);
    for (size_t j = 0; j < K; ++j) {
      const ParamSpec& s = table_[size_t(bases_[j].lin)];
      // A paired basis carries u or v ≥ 0; L = u + v is bounded below by 0 (pair_affine checks).
      lo[Eigen::Index(j)] = bases_[j].affine >= 0 ? 0.0 : s.lower;
      hi[Eigen::Index(j)] = bases_[j].affine >= 0 ? std::numeric_limits<double>::infinity() : s.upper;
    }
    for (int c = 0; c < 3; ++c) {
      Eigen::MatrixXd A = Eigen::MatrixXd::Zero(Eigen::Index(K), Eigen::Index(K));
      Eigen::VectorXd y = Eigen::VectorXd::Zero(Eigen::Index(K));
      for (size_t i = 0; i < metric_.chunk_count(); ++i) {  // chunk order: deterministic sums
        const double* a = partial.data() + i * stride + size_t(c) * (K * K + K);
        for (size_t j = 0; j < K; ++j) {
          for (size_t l = j; l < K; ++l) A(Eigen::Index(j), Eigen::Index(l)) += a[j * K + l];
          y[Eigen::Index(j)] += a[K * K + j];
        }
      }
      A = A.selfadjointView<Eigen::Upper>();
      if (!A.allFinite() || !y.allFinite()) return false;
      const Eigen::VectorXd beta = box_least_squares(A, y, lo, hi);
      auto& v = pv.values[size_t(c)];
      for (size_t j = 0; j < K; ++j) {
        const Basis& b = bases_[j];
        if (b.affine < 0) {
          v[size_t(b.lin)] = beta[Eigen::Index(j)];
        } else if (b.affine_value == table_[size_t(b.affine)].lower) {  // the pair (v, u) starts here
          const double lo_coef = beta[Eigen::Index(j)], hi_coef = beta[Eigen::Index(j + 1)];
          const ParamSpec& L = table_[size_t(b.lin)];
          const ParamSpec& P = table_[size_t(b.affine)];
          const double sum = lo_coef + hi_coef;
          // L above its upper bound is clamped (documented limitation of the pairing).
          v[size_t(b.lin)] = std::min(sum, L.upper);
          if (sum > 0) v[size_t(b.affine)] = P.lower + (P.upper - P.lower) * hi_coef / sum;
        }
      }
    }
    return true;
  }

  // Residuals at pv; with projection the colours are solved first (and written into pv).
  bool residuals(ParamValues& pv, double* r) {
    if (project_) {
      if (!project(pv)) return false;
    }
    const double scale = metric_.scale();
    std::vector<unsigned char> ok(metric_.chunk_count(), 1);
    tbb::parallel_for(size_t(0), metric_.chunk_count(), [&](size_t i) {
      const MetricChunk& ch = chunk(i);
      const size_t off = offset_[i];
      const SoaPairs d{ch.wi_x.data(), ch.wi_y.data(), ch.wi_z.data(), ch.wo_x.data(), ch.wo_y.data(), ch.wo_z.data()};
      bool finite = true;
      for (int c = 0; c < 3; ++c) {
        double* out = r + size_t(c) * n_ + off;
        const auto& m = ch.measured[size_t(c)];
        if (project_) {
          // ρ from the stored bases: the model need not be evaluated again.
          const int q = classes_ == 1 ? 0 : c;
          const size_t K = bases_.size();
          for (size_t k = 0; k < ch.size(); ++k) out[k] = -m[k];
          for (size_t j = 0; j < K; ++j) {
            const double coef = coefficient(pv, c, j);
            const double* b = basis_[size_t(q) * K + j].data() + off;
            for (size_t k = 0; k < ch.size(); ++k) out[k] += coef * b[k];
          }
          for (size_t k = 0; k < ch.size(); ++k) out[k] *= scale * ch.sqrt_weight[k] * ch.factor[k];
        } else {
          const Transform t = metric_.transform();
          eval_pairs(model_, fast_, pv.channel(c), c, ch.size(), d, out);
          for (size_t k = 0; k < ch.size(); ++k) {
            const double f = ch.factor[k];
            out[k] = scale * ch.sqrt_weight[k] * (apply_transform(t, f * out[k]) - apply_transform(t, f * m[k]));
          }
        }
        for (size_t k = 0; k < ch.size(); ++k) finite = finite && std::isfinite(out[k]);
      }
      ok[i] = finite;
    });
    for (unsigned char o : ok)
      if (!o) return false;
    return true;
  }

  // Colours from the identity-transform projection, whatever the metric: starting values for
  // a metric that cannot project (seed 003 fits its E2 with every parameter free).
  bool initial_colours(ParamValues& pv) {
    if (project_) return project(pv);
    return true;
  }

 private:
  const MetricChunk& chunk(size_t i) const {
    static thread_local MetricChunk unused;
    return metric_.chunk(i, unused);
  }

  // Coefficient of basis j in channel c from the parameter values (the inverse of project()'s map).
  double coefficient(const ParamValues& pv, int c, size_t j) const {
    const Basis& b = bases_[j];
    const auto& v = pv.values[size_t(c)];
    const double L = v[size_t(b.lin)];
    if (b.affine < 0) return L;
    const ParamSpec& P = table_[size_t(b.affine)];
    const double t = (v[size_t(b.affine)] - P.lower) / (P.upper - P.lower);
    return b.affine_value == P.lower ? L * (1 - t) : L * t;
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
  // defaults and at another point of the bounds): then it is evaluated once per fit.
  bool shape_independent(size_t j) const {
    const ParamValues pv = ParamValues::defaults(table_);
    for (int c = 0; c < classes_; ++c) {
      std::vector<double> a = pv.values[size_t(c)];
      for (const Basis& b : bases_) a[size_t(b.lin)] = 0.0;
      a[size_t(bases_[j].lin)] = 1.0;
      if (bases_[j].affine >= 0) a[size_t(bases_[j].affine)] = bases_[j].affine_value;
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

  // Whether channel c changes the model's value at equal parameters (wavelength-dependent
  // models do): probed at a few fixed direction pairs; if not, one basis serves R, G and B.
  bool channel_independent() const {
    for (const Var& v : vars_)
      if (v.channel >= 0) return false;
    const ParamValues pv = ParamValues::defaults(table_);
    std::vector<double> p = pv.values[0];
    for (const Basis& b : bases_) p[size_t(b.lin)] = 1.0;
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
  BatchEvalFn fast_;
  std::vector<size_t> offset_;
  size_t n_ = 0;
  bool project_ = false;
  std::vector<Basis> bases_;
  std::vector<Var> vars_;
  int classes_ = 3;
  std::vector<std::vector<double>> basis_;
  std::vector<bool> constant_;
  bool bases_ready_ = false;
};

// The projected (or plain) residual as one Ceres cost with forward-difference derivatives
// (DESIGN.md §12: one block, parallel inside).
class ProjectedCost final : public ceres::CostFunction {
 public:
  ProjectedCost(Problem& problem, const ParamValues& base) : problem_(problem), base_(base) {
    set_num_residuals(int(problem.residual_count()));
    mutable_parameter_block_sizes()->push_back(int(problem.vars().size()));
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const auto& vars = problem_.vars();
    const size_t n = vars.size(), m = problem_.residual_count();
    // Ceres evaluates a trial point without derivatives, then again with them once accepted:
    // the second residual evaluation is served from here.
    if (!last_r_.empty() && std::equal(last_x_.begin(), last_x_.end(), parameters[0])) {
      std::copy(last_r_.begin(), last_r_.end(), residuals);
    } else {
      ParamValues pv = base_;
      problem_.to_values(parameters[0], pv);
      last_r_.clear();
      if (!problem_.residuals(pv, residuals)) return false;
      last_x_.assign(parameters[0], parameters[0] + n);
      last_r_.assign(residuals, residuals + m);
    }
    if (!jacobians || !jacobians[0]) return true;
    std::vector<double> x(parameters[0], parameters[0] + n), rh(m);
    for (size_t v = 0; v < n; ++v) {
      const ParamSpec& s = problem_.table()[size_t(vars[v].param)];
      double h = 1e-6 * std::max(std::abs(x[v]), 1e-3);
      if (x[v] + h > s.upper) h = -h;  // stay inside the bounds
      std::vector<double> xh = x;
      xh[v] += h;
      ParamValues ph = base_;
      problem_.to_values(xh.data(), ph);
      if (!problem_.residuals(ph, rh.data())) return false;
      double* J = jacobians[0];
      const double inv = 1.0 / h;
      tbb::parallel_for(tbb::blocked_range<size_t>(0, m, 1 << 16), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t k = r.begin(); k < r.end(); ++k) J[k * n + v] = (rh[k] - residuals[k]) * inv;
      });
    }
    return true;
  }

 private:
  Problem& problem_;
  ParamValues base_;
  mutable std::vector<double> last_x_, last_r_;
};

double draw(const ParamSpec& s, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double t = u(rng);
  if (!std::isfinite(s.lower) || !std::isfinite(s.upper)) return s.def;
  if (s.lower > 0 && s.upper / s.lower > 100) return s.lower * std::pow(s.upper / s.lower, t);
  return s.lower + t * (s.upper - s.lower);
}

}  // namespace

FitResult fit_model(const Model& model, const Metric& metric, const FitOptions& options) {
  if (options.starts < 1) throw InputError("--starts", "must be at least 1");
  if (options.max_iterations < 1) throw InputError("--max-iterations", "must be at least 1");
  if (!metric.cached())
    throw InputError("metric '" + std::string(metric.id()) + "'",
                     "is for reports only (its grid is too large to keep); fit under ngan, bagher, low-e1 or low-e2");
  const auto t0 = std::chrono::steady_clock::now();
  Problem problem(model, metric);
  const ParamTable& table = problem.table();
  const size_t n = problem.vars().size();
  if (n == 0 && !problem.has_linear())
    throw InputError("model '" + std::string(model.name()) + "'", "has no free parameter to fit");

  std::mt19937_64 rng(options.seed);
  FitResult best;
  double best_cost = std::numeric_limits<double>::infinity();
  int total_iterations = 0;
  std::vector<double> residual(problem.residual_count());
  for (int start = 0; start < options.starts; ++start) {
    ParamValues pv = ParamValues::defaults(table);
    if (start > 0)
      for (const Var& v : problem.vars()) {
        const double x = draw(table[size_t(v.param)], rng);
        for (int c = 0; c < 3; ++c)
          if (v.channel < 0 || v.channel == c) pv.values[size_t(c)][size_t(v.param)] = x;
      }
    if (!problem.initial_colours(pv)) continue;
    std::vector<double> x(n);
    problem.from_values(pv, x.data());
    double cost;
    bool converged = true;
    std::string message = "colours only: solved directly";
    if (n > 0) {
      ceres::Problem::Options popt;
      popt.cost_function_ownership = ceres::TAKE_OWNERSHIP;
      ceres::Problem cp(popt);
      cp.AddResidualBlock(new ProjectedCost(problem, pv), nullptr, x.data());
      for (size_t v = 0; v < n; ++v) {
        const ParamSpec& s = table[size_t(problem.vars()[v].param)];
        cp.SetParameterLowerBound(x.data(), int(v), s.lower);
        cp.SetParameterUpperBound(x.data(), int(v), s.upper);
      }
      ceres::Solver::Options so;
      so.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
      so.max_num_iterations = options.max_iterations;
      so.function_tolerance = 1e-12;
      so.gradient_tolerance = 1e-14;
      so.parameter_tolerance = 1e-10;
      so.logging_type = ceres::SILENT;
      so.num_threads = 1;  // the cost function is parallel inside
      ceres::Solver::Summary summary;
      ceres::Solve(so, &cp, &summary);
      total_iterations += int(summary.iterations.size()) - 1;
      if (!summary.IsSolutionUsable()) continue;
      converged = summary.termination_type == ceres::CONVERGENCE;
      message = summary.message;
      problem.to_values(x.data(), pv);
    }
    if (!problem.residuals(pv, residual.data())) continue;
    double sum = 0;
    for (double r : residual) sum += r * r;
    cost = sum;
    bool finite = std::isfinite(cost);
    for (const auto& ch : pv.values)
      for (double v : ch) finite = finite && std::isfinite(v);
    if (finite && cost < best_cost) {
      best_cost = cost;
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
  best.metric_value = metric.value(model, best.values);
  return best;
}

}  // namespace brdfkit::fit
