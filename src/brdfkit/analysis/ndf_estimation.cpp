#include "brdfkit/analysis/ndf_estimation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <boost/math/tools/minima.hpp>

#include "brdfkit/core/error.h"
#include "brdfkit/fresnel/schlick.h"

namespace brdfkit::analysis {

namespace {

using Stencil = HemisphereTable::Stencil;

// How the table of D is laid out: which nodes a half vector's D mixes, the roughness penalty's
// triples, the normalization and the masking G1 of a table.
class TableLayout {
 public:
  virtual ~TableLayout() = default;
  virtual int size() const = 0;
  virtual Stencil locate(const Vec3d& h) const = 0;
  virtual std::vector<std::array<int, 3>> second_differences() const = 0;
  virtual double mass(const std::vector<double>& d) const = 0;  // ∫ D cosθ dω
  virtual std::function<double(const Vec3d&)> masking(const std::vector<double>& d) const = 0;
};

// D(θ) linear between the angles θ_j (ndf/tabulated.h), masked as TabulatedCookTorrance.
class ThetaLayout final : public TableLayout {
 public:
  explicit ThetaLayout(int n) {
    for (int j = 0; j < n; ++j) {
      const double u = double(j) / (n - 1);
      theta_.push_back(u * u * kPi / 2);  // seed 002 §5.1 leaves the table open; MERL's θh spacing
    }
  }
  const std::vector<double>& theta() const { return theta_; }
  int size() const override { return int(theta_.size()); }
  Stencil locate(const Vec3d& h) const override {
    const double th = std::acos(std::clamp(h.z(), -1.0, 1.0));
    int j = int(std::upper_bound(theta_.begin(), theta_.end(), th) - theta_.begin()) - 1;
    j = std::clamp(j, 0, int(theta_.size()) - 2);
    const double t = std::clamp((th - theta_[size_t(j)]) / (theta_[size_t(j) + 1] - theta_[size_t(j)]), 0.0, 1.0);
    Stencil s;
    s.node = {j, j + 1, 0, 0};
    s.weight = {1 - t, t, 0, 0};
    s.count = 2;
    return s;
  }
  std::vector<std::array<int, 3>> second_differences() const override {
    std::vector<std::array<int, 3>> out;
    for (int j = 1; j + 1 < size(); ++j) out.push_back({j - 1, j, j + 1});
    return out;
  }
  double mass(const std::vector<double>& d) const override {
    const Tabulated<double> ndf(theta_, d);  // InputError if all zero: no specular signal
    double raw = 0, normalized = 0;
    for (size_t j = 0; j < d.size(); ++j) {
      raw += d[j];
      normalized += ndf.value[j];
    }
    return raw / normalized;
  }
  std::function<double(const Vec3d&)> masking(const std::vector<double>& d) const override {
    auto model = std::make_shared<const TabulatedCookTorrance>(theta_, d);
    return [model](const Vec3d& w) { return model->masking().g1(w.z()); };
  }

 private:
  std::vector<double> theta_;
};

class HemisphereLayout final : public TableLayout {
 public:
  HemisphereLayout(int rings, int azimuths) : table_(rings, azimuths) {}
  const HemisphereTable& table() const { return table_; }
  int size() const override { return table_.nodes(); }
  Stencil locate(const Vec3d& h) const override { return table_.locate(h); }
  std::vector<std::array<int, 3>> second_differences() const override { return table_.second_differences(); }
  double mass(const std::vector<double>& d) const override {
    const double m = table_.mass(d);
    if (!(m > 0)) throw InputError("ndf estimation", "the estimated distribution is zero: no specular signal");
    return m;
  }
  std::function<double(const Vec3d&)> masking(const std::vector<double>& d) const override {
    auto m = std::make_shared<const HemisphereTable::Masking>(table_.masking(d));
    return [m](const Vec3d& w) { return m->g1(w); };
  }

 private:
  HemisphereTable table_;
};

// The metric's samples, reduced to what the linear solves need: the residual of sample k,
// channel c is a_k (ρ_c − m_c) (a = √w · f of fit/metric.h, identity transform), and ρ_c =
// kd_c/π + ks_c F(θd) D(h) G1(wi) G1(wo)/(4 cosθi cosθo) with D(h) = Σ weight · D[node] over the
// sample's stencil.
struct Samples {
  std::vector<Vec3d> wi, wo;
  std::vector<double> a, cd;
  std::vector<Stencil> at;
  std::array<std::vector<double>, 3> y;  // a · m_c
  size_t size() const { return a.size(); }
};

void add_sample(Samples& s, const TableLayout& layout, const Vec3d& wi, const Vec3d& wo, double a, const Rgb& m) {
  if (!(wi.z() > 0 && wo.z() > 0) || !(a > 0) || !m.allFinite()) return;
  const Vec3d sum = wi + wo;
  const double len = sum.norm();
  s.wi.push_back(wi);
  s.wo.push_back(wo);
  s.a.push_back(a);
  s.cd.push_back(0.5 * len);
  s.at.push_back(layout.locate(sum / len));
  for (int c = 0; c < 3; ++c) s.y[size_t(c)].push_back(a * m[c]);
}

Samples gather(const fit::Metric& metric, const TableLayout& layout) {
  Samples s;
  fit::MetricChunk scratch;
  for (size_t i = 0; i < metric.chunk_count(); ++i) {
    const fit::MetricChunk& ch = metric.chunk(i, scratch);
    for (size_t k = 0; k < ch.size(); ++k) {
      const Vec3d wi(ch.wi_x[k], ch.wi_y[k], ch.wi_z[k]), wo(ch.wo_x[k], ch.wo_y[k], ch.wo_z[k]);
      add_sample(s, layout, wi, wo, ch.sqrt_weight[k] * ch.factor[k],
                 Rgb(ch.measured[0][k], ch.measured[1][k], ch.measured[2][k]));
    }
  }
  return s;
}

// The data's own samples with ngan's weighting (seed 002 Eq. 1: residuals of ρ cosθi, w the
// sample's measure, which for MERL cells already carries the sines of the solid angles).
Samples gather(const SampleSet& set, const TableLayout& layout) {
  Samples s;
  for (size_t k = 0; k < set.size(); ++k)
    if (set.valid[k]) add_sample(s, layout, set.wi(k), set.wo(k), std::sqrt(set.weight[k]) * set.wi_z[k], set.value(k));
  return s;
}

// The table block's sparsity pattern in the normal equations: the node pairs (a ≤ b) that share a
// sample's stencil or a penalty triple. It is fixed by the samples, so each sample's slots are
// found once and every solve only adds numbers.
class TablePattern {
 public:
  TablePattern(const Samples& s, const std::vector<std::array<int, 3>>& penalty) {
    std::vector<std::uint64_t> keys;
    for (const Stencil& at : s.at)
      for (int q = 0; q < at.count; ++q)
        for (int r = q; r < at.count; ++r) keys.push_back(key(at.node[size_t(q)], at.node[size_t(r)]));
    for (const auto& t : penalty)
      for (size_t a = 0; a < 3; ++a)
        for (size_t b = a; b < 3; ++b) keys.push_back(key(t[a], t[b]));
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    keys_ = std::move(keys);
    for (const Stencil& at : s.at) {
      begin_.push_back(slots_.size());
      for (int q = 0; q < at.count; ++q)
        for (int r = q; r < at.count; ++r) slots_.push_back(slot(at.node[size_t(q)], at.node[size_t(r)]));
    }
  }
  size_t size() const { return keys_.size(); }
  int slot(int a, int b) const {
    return int(std::lower_bound(keys_.begin(), keys_.end(), key(a, b)) - keys_.begin());
  }
  // The slots of sample k's stencil pairs (q ≤ r, q outer), in that order.
  const int* sample_slots(size_t k) const { return slots_.data() + begin_[k]; }
  int row(size_t slot) const { return int(keys_[slot] >> 32); }
  int col(size_t slot) const { return int(keys_[slot] & 0xffffffffu); }

 private:
  static std::uint64_t key(int a, int b) {
    return (std::uint64_t(std::min(a, b)) << 32) | std::uint64_t(std::max(a, b));
  }
  std::vector<std::uint64_t> keys_;
  std::vector<int> slots_;
  std::vector<size_t> begin_;
};

// Solves the symmetric normal equations m x = rhs (m given in full) holding variables at 0 that come
// out negative, until none does (an active-set approximation of NNLS that suffices here: the
// penalty keeps the system well conditioned). Sparse LDLᵀ: the table block couples neighbours only.
Eigen::VectorXd solve_nonnegative(const Eigen::SparseMatrix<double>& m, const Eigen::VectorXd& rhs) {
  const int n = int(rhs.size());
  std::vector<int> index(static_cast<size_t>(n));  // variable → row among the free ones, −1 when held at 0
  for (int i = 0; i < n; ++i) index[size_t(i)] = i;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  for (int round = 0; round < 50; ++round) {
    std::vector<int> free;
    for (int i = 0; i < n; ++i)
      if (index[size_t(i)] >= 0) index[size_t(i)] = int(free.size()), free.push_back(i);
    std::vector<Eigen::Triplet<double>> entries;
    for (int c = 0; c < m.outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(m, c); it; ++it)
        if (index[size_t(it.row())] >= 0 && index[size_t(it.col())] >= 0)
          entries.emplace_back(index[size_t(it.row())], index[size_t(it.col())], it.value());
    Eigen::SparseMatrix<double> mf(Eigen::Index(free.size()), Eigen::Index(free.size()));
    mf.setFromTriplets(entries.begin(), entries.end());
    Eigen::VectorXd rf(free.size());
    for (size_t a = 0; a < free.size(); ++a) rf[Eigen::Index(a)] = rhs[free[a]];
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(mf);
    if (ldlt.info() != Eigen::Success) throw InputError("ndf estimation", "the normal equations are singular");
    const Eigen::VectorXd xf = ldlt.solve(rf);
    x.setZero();
    bool negative = false;
    for (size_t a = 0; a < free.size(); ++a) {
      const double v = xf[Eigen::Index(a)];
      if (!(v >= 0)) {
        index[size_t(free[a])] = -1;
        negative = true;
      } else {
        x[free[a]] = v;
      }
    }
    if (!negative) break;
  }
  return x;
}

// One Anderson step (Walker & Ni 2011, Eq. 2.1–2.2): from inputs xs and outputs phis = Φ(xs),
// most recent last, the next input min ‖f_k − ΔF γ‖ over the last `depth` residual differences
// (f = Φ(x) − x), clamped to D ≥ 0; the plain step Φ(x_k) when there is no difference yet or the
// least-squares solve fails.
Eigen::VectorXd anderson_step(const std::vector<Eigen::VectorXd>& xs, const std::vector<Eigen::VectorXd>& phis,
                              int depth) {
  const Eigen::VectorXd& phi = phis.back();
  const size_t h = xs.size();
  const int m = int(std::min<size_t>(size_t(depth), h - 1));
  if (m == 0) return phi;
  Eigen::MatrixXd df(phi.size(), m), dphi(phi.size(), m);
  for (int i = 0; i < m; ++i) {
    const size_t a = h - 1 - size_t(i), b = a - 1;
    df.col(i) = (phis[a] - xs[a]) - (phis[b] - xs[b]);
    dphi.col(i) = phis[a] - phis[b];
  }
  const Eigen::VectorXd gamma = df.colPivHouseholderQr().solve(phi - xs.back());
  if (!gamma.allFinite()) return phi;
  return (phi - dphi * gamma).cwiseMax(0.0);
}

struct State {
  std::vector<double> d;        // normalized D at the nodes
  std::array<double, 3> kd{}, ks{};
};

// One estimate, whatever the table's layout.
struct Outcome {
  State state;
  int iterations = 0;
  double f0 = 0;
  std::vector<double> residual_history;
};

class Estimator {
 public:
  // finish: the sum of squared residuals → the reported number (the metric's post-processing).
  // `layout` must outlive the estimator.
  template <class Source>
  Estimator(const Source& source, const TableLayout& layout, std::function<double(double)> finish,
            const NdfEstimationOptions& opt)
      : layout_(layout),
        finish_(std::move(finish)),
        opt_(opt),
        penalty_(layout.second_differences()),
        s_(gather(source, layout)),
        pattern_(s_, penalty_) {
    if (s_.size() == 0) throw InputError("ndf estimation", "no valid sample to estimate from");
  }

  // The estimate for a given F0, with `iterations` masking recomputations at most, the first solve
  // masked by `start` (empty: the constant 1 of seed 002 §5.1).
  Outcome run(double f0, int iterations, std::function<double(const Vec3d&)> start = {}) const {
    Outcome e;
    e.f0 = f0;
    const size_t n = s_.size();
    std::vector<double> fresnel(n), g(n);
    const SchlickFresnel<double> schlick(&f0);
    for (size_t k = 0; k < n; ++k) fresnel[k] = schlick.eval(s_.cd[k]);
    State& st = e.state;
    st.ks = {1.0, 1.0, 1.0};
    // The masking recomputation is a fixed point D = Φ(D) (Φ: masking of D, then the linear solve)
    // that plain iteration approaches only linearly: on a synthetic GGX α = 0.2 table the residual
    // fell by ≈ 0.57 per iteration and D was still 6.1 % off at 60° after five (0.44 % with Anderson). Anderson
    // acceleration (Walker & Ni 2011, Eq. 2.1–2.2; depth 3) mixes the last Φ outputs so that the
    // ≤ 5 iterations of seed 002 §5.1 suffice. The masking is built from the mixed D (x), the
    // reported D is the last Φ output (consistent with the solved kd, ks).
    constexpr int kDepth = 3;
    std::vector<Eigen::VectorXd> xs, phis;  // inputs x_k and outputs Φ(x_k), most recent last
    std::function<double(const Vec3d&)> g1 = std::move(start);
    for (int it = 0; it <= iterations; ++it) {
      // Masking: `start` at first, then from the current D.
      weights(g1, fresnel, g);
      for (int inner = 0; inner < 2; ++inner) {
        solve_table(g, st);
        solve_colours(g, st);
      }
      e.iterations = it;
      e.residual_history.push_back(residual(g, st));
      const Eigen::VectorXd phi = Eigen::Map<const Eigen::VectorXd>(st.d.data(), Eigen::Index(st.d.size()));
      if (it == iterations) break;
      if (!xs.empty()) {  // x_k was the input of this Φ
        const Eigen::VectorXd& x = xs.back();
        if ((phi - x).cwiseAbs().maxCoeff() <= opt_.tolerance * phi.maxCoeff()) break;
        phis.push_back(phi);
      }
      const Eigen::VectorXd next = xs.empty() ? phi : anderson_step(xs, phis, kDepth);
      xs.push_back(next);
      if (xs.size() > size_t(kDepth) + 1) xs.erase(xs.begin()), phis.erase(phis.begin());
      std::vector<double> d(next.data(), next.data() + next.size());
      const double mass = layout_.mass(d);
      for (double& v : d) v /= mass;
      g1 = layout_.masking(d);
    }
    return e;
  }

 private:
  // g = a F G / (4 cosθi cosθo) per sample, the factor of D in the model; G = 1 without a masking.
  void weights(const std::function<double(const Vec3d&)>& g1, const std::vector<double>& fresnel,
               std::vector<double>& g) const {
    for (size_t k = 0; k < g.size(); ++k) {
      const double mask = g1 ? g1(s_.wi[k]) * g1(s_.wo[k]) : 1.0;
      g[k] = s_.a[k] * fresnel[k] * mask / (4 * s_.wi[k].z() * s_.wo[k].z());
    }
  }

  // With ks fixed per channel: linear least squares in (kd_R, kd_G, kd_B, D_0 … D_{N−1}) plus a
  // small second-difference penalty (nodes without data, e.g. θh > 80° under `ngan`, follow
  // their neighbours); then D is normalized and the scale moves into ks.
  void solve_table(const std::vector<double>& g, State& st) const {
    const int nn = layout_.size(), nv = 3 + nn;
    std::vector<double> table(pattern_.size(), 0.0);  // the table block, by TablePattern slot
    Eigen::Matrix<double, 3, Eigen::Dynamic> coupling = Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, nn);
    Eigen::Vector3d diffuse = Eigen::Vector3d::Zero();
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(nv);
    const double ks2 = st.ks[0] * st.ks[0] + st.ks[1] * st.ks[1] + st.ks[2] * st.ks[2];
    for (size_t k = 0; k < s_.size(); ++k) {
      const Stencil& at = s_.at[k];
      const double ad = s_.a[k] * kInvPi;
      const int* slot = pattern_.sample_slots(k);
      for (int c = 0; c < 3; ++c) {
        diffuse[c] += ad * ad;
        rhs[c] += ad * s_.y[size_t(c)][k];
      }
      for (int q = 0; q < at.count; ++q) {
        const int n = at.node[size_t(q)];
        const double bq = g[k] * at.weight[size_t(q)];
        for (int c = 0; c < 3; ++c) {
          coupling(c, n) += ad * st.ks[size_t(c)] * bq;
          rhs[3 + n] += st.ks[size_t(c)] * bq * s_.y[size_t(c)][k];
        }
        for (int r = q; r < at.count; ++r) table[size_t(*slot++)] += bq * g[k] * at.weight[size_t(r)] * ks2;
      }
    }
    double diagonal = 0;
    for (size_t i = 0; i < table.size(); ++i)
      if (pattern_.row(i) == pattern_.col(i)) diagonal += table[i];
    const double scale = diagonal / nn > 0 ? diagonal / nn : 1.0;
    const double lambda = opt_.smoothing * scale;
    for (const auto& idx : penalty_) {
      const double w[3] = {1, -2, 1};
      for (size_t a = 0; a < 3; ++a)
        for (size_t b = a; b < 3; ++b) table[size_t(pattern_.slot(idx[a], idx[b]))] += lambda * w[a] * w[b];
    }
    std::vector<Eigen::Triplet<double>> entries;
    for (int c = 0; c < 3; ++c) {
      entries.emplace_back(c, c, diffuse[c]);
      for (int n = 0; n < nn; ++n)
        if (coupling(c, n) != 0) entries.emplace_back(c, 3 + n, coupling(c, n)), entries.emplace_back(3 + n, c, coupling(c, n));
    }
    // A node no sample and no penalty reaches (smoothing 0) keeps a 10⁻¹² ridge: the solve stays
    // definite and the node comes out 0.
    for (int n = 0; n < nn; ++n) entries.emplace_back(3 + n, 3 + n, 1e-12 * scale);
    for (size_t i = 0; i < table.size(); ++i) {
      const int a = 3 + pattern_.row(i), b = 3 + pattern_.col(i);
      entries.emplace_back(a, b, table[i]);
      if (a != b) entries.emplace_back(b, a, table[i]);
    }
    Eigen::SparseMatrix<double> m(nv, nv);
    m.setFromTriplets(entries.begin(), entries.end());
    const Eigen::VectorXd x = solve_nonnegative(m, rhs);
    std::vector<double> raw(static_cast<size_t>(nn), 0.0);
    for (int j = 0; j < nn; ++j) raw[size_t(j)] = x[3 + j];
    const double mass = layout_.mass(raw);  // InputError if all zero: no specular signal
    st.d = raw;
    for (double& v : st.d) v /= mass;
    for (int c = 0; c < 3; ++c) {
      st.kd[size_t(c)] = x[c];
      st.ks[size_t(c)] *= mass;
    }
  }

  double d_at(const State& st, size_t k) const { return s_.at[k].apply(st.d); }

  // With D fixed: per channel, (kd, ks) ≥ 0 by 2×2 least squares (variable projection, seed 002 §3).
  void solve_colours(const std::vector<double>& g, State& st) const {
    for (int c = 0; c < 3; ++c) {
      double aa = 0, ab = 0, bb = 0, ay = 0, by = 0;
      for (size_t k = 0; k < s_.size(); ++k) {
        const double a = s_.a[k] * kInvPi, b = g[k] * d_at(st, k), y = s_.y[size_t(c)][k];
        aa += a * a;
        ab += a * b;
        bb += b * b;
        ay += a * y;
        by += b * y;
      }
      const double det = aa * bb - ab * ab;
      double kd = det > 0 ? (ay * bb - by * ab) / det : 0, ks = det > 0 ? (by * aa - ay * ab) / det : 0;
      if (!(kd >= 0)) {
        kd = 0;
        ks = bb > 0 ? std::max(0.0, by / bb) : 0;
      } else if (!(ks >= 0)) {
        ks = 0;
        kd = aa > 0 ? std::max(0.0, ay / aa) : 0;
      }
      st.kd[size_t(c)] = kd;
      st.ks[size_t(c)] = ks;
    }
  }

  double residual(const std::vector<double>& g, const State& st) const {
    double sum = 0;
    for (size_t k = 0; k < s_.size(); ++k) {
      const double dk = g[k] * d_at(st, k), ad = s_.a[k] * kInvPi;
      for (int c = 0; c < 3; ++c) {
        const double r = ad * st.kd[size_t(c)] + st.ks[size_t(c)] * dk - s_.y[size_t(c)][k];
        sum += r * r;
      }
    }
    return finish_(sum);
  }

  const TableLayout& layout_;
  std::function<double(double)> finish_;
  NdfEstimationOptions opt_;
  std::vector<std::array<int, 3>> penalty_;
  Samples s_;
  TablePattern pattern_;
};

const NdfEstimationOptions& checked(const NdfEstimationOptions& opt) {
  if (opt.max_iterations < 0 || opt.max_iterations > 50)
    throw InputError("ndf estimation", "iterations must be in [0, 50]");
  if (opt.nodes < 8 || opt.nodes > 2000) throw InputError("ndf estimation", "nodes must be in [8, 2000]");
  if (opt.rings < 4 || opt.rings > 64 || opt.azimuths < 4 || opt.azimuths > 128)
    throw InputError("ndf estimation", "rings must be in [4, 64] and azimuths in [4, 128]");
  if (opt.f0 && !(*opt.f0 >= 0 && *opt.f0 <= 1)) throw SettingError("f0", "must be in [0, 1]");
  if (!(opt.smoothing >= 0)) throw InputError("ndf estimation", "smoothing must be >= 0");
  return opt;
}

// `start`: the masking the iterations start from (nullptr: the constant one of seed 002 §5.1).
Outcome run(const Estimator& est, const NdfEstimationOptions& opt, const std::function<double(const Vec3d&)>& start = {}) {
  if (opt.f0) return est.run(*opt.f0, opt.max_iterations, start);
  // F0 in the outermost loop (seed 002 §5.1): Brent on the residual, two masking iterations per
  // trial (the masking moves little with F0), then the full estimate at the best F0.
  const auto best = boost::math::tools::brent_find_minima(
      [&](double f0) { return est.run(f0, std::min(2, opt.max_iterations), start).residual_history.back(); }, 0.0, 1.0, 12);
  return est.run(best.first, opt.max_iterations, start);
}

// kd, ks, F0 per channel: TabulatedCookTorrance's parameters.
ParamValues colours(const Outcome& o) {
  ParamValues v;
  for (size_t c = 0; c < 3; ++c) v.values[c] = {o.state.kd[c], o.state.ks[c], o.f0};
  return v;
}

NdfEstimate isotropic(const Outcome& o, const ThetaLayout& layout) {
  NdfEstimate e;
  e.theta = layout.theta();
  e.d = o.state.d;
  e.values = colours(o);
  e.iterations = o.iterations;
  e.f0 = o.f0;
  e.residual_history = o.residual_history;
  return e;
}

double weight_sum(const SampleSet& samples) {
  double wsum = 0;
  for (size_t k = 0; k < samples.size(); ++k)
    if (samples.valid[k]) wsum += samples.weight[k];
  if (!(wsum > 0)) throw InputError("ndf estimation", "no valid sample to estimate from");
  return wsum;
}

}  // namespace

NdfEstimate estimate_tabulated_ndf(const fit::Metric& metric, const NdfEstimationOptions& opt) {
  if (metric.transform() != fit::Transform::Identity)
    throw InputError("metric '" + std::string(metric.id()) + "'",
                     "tabulated-NDF estimation needs a metric whose residual is linear in rho (not low-e2)");
  const ThetaLayout layout(checked(opt).nodes);
  const Estimator est(metric, layout,
                      [&metric](double sum) { return metric.finish(metric.scale() * metric.scale() * sum); }, opt);
  return isotropic(run(est, opt), layout);
}

NdfEstimate estimate_tabulated_ndf(const SampleSet& samples, const NdfEstimationOptions& opt) {
  const double wsum = weight_sum(samples);
  const ThetaLayout layout(checked(opt).nodes);
  const Estimator est(samples, layout, [wsum](double sum) { return std::sqrt(sum / wsum); }, opt);
  return isotropic(run(est, opt), layout);
}

AnisotropicNdfEstimate estimate_anisotropic_ndf(const SampleSet& samples, const NdfEstimationOptions& opt) {
  const double wsum = weight_sum(samples);
  auto finish = [wsum](double sum) { return std::sqrt(sum / wsum); };
  // The isotropic estimate first: its masking (that of the azimuthal mean of D) is the start of the
  // hemisphere table's iteration. From the constant masking of seed 002 §5.1 the hemisphere table
  // converges slowly (GGX αx 0.2, αy 0.4: D still 26 % off at 55° after five Anderson-accelerated
  // iterations, 2 % at the fixed point); from this start five suffice. F0, when not given, is
  // searched again with the hemisphere table: the isotropic estimate's F0 fits the mean of D, not D
  // (0.26 for that lobe with F0 = 0.5, and then the table's iteration diverged: D 5× off at its peak).
  const ThetaLayout theta_layout(checked(opt).nodes);
  const Outcome mean = run(Estimator(samples, theta_layout, finish, opt), opt);
  const auto start = theta_layout.masking(mean.state.d);
  const HemisphereLayout layout(opt.rings, opt.azimuths);
  const Outcome o = run(Estimator(samples, layout, finish, opt), opt, start);
  return {layout.table(), o.state.d, colours(o), o.iterations, o.f0, o.residual_history};
}

}  // namespace brdfkit::analysis
