#include "brdfkit/fit/engine/plain_objective.h"

#include <Eigen/Dense>

#include "brdfkit/core/ordered_reduce.h"
#include "brdfkit/fit/engine/finite_difference.h"

namespace brdfkit::fit {

using Eigen::Index;

// Block i: Σ r² (acc[0]), Jᵀr (acc[1 + u]) and the upper triangle of JᵀJ (acc[1 + nv + u·nv + v]).
void PlainObjective::block_partials(size_t i, const ParamValues& pv, const std::vector<ParamValues>& shifted,
                                    const std::vector<double>& h, bool derivatives, double* acc) const {
  const size_t nv = ctx_.vars.size();
  const SampleBlock& b = ctx_.blocks[i];
  std::vector<double> rho(b.n), r(3 * b.n), J(derivatives ? nv * 3 * b.n : 0, 0.0);
  auto residual = [&](const ParamValues& p, int c, double* dst) {
    ctx_.model.eval_batch(p.channel(c), c, b.n, b.d, rho.data());
    for (size_t k = 0; k < b.n; ++k)
      dst[k] = metric_residual(ctx_.transform, b.rw[k], b.f[k], rho[k],
                               transformed_measured(ctx_.transform, b.f[k], b.m[c][k]));
  };
  for (int c = 0; c < 3; ++c) residual(pv, c, r.data() + size_t(c) * b.n);
  for (double v : r) acc[0] += v * v;
  if (!derivatives) return;
  for (size_t v = 0; v < nv; ++v)
    for (int c = 0; c < 3; ++c) {
      if (!ctx_.vars[v].affects(c)) continue;
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
}

bool PlainObjective::evaluate(const double* x, bool derivatives, ObjectiveValue& out, ParamValues& values) {
  const size_t nv = ctx_.vars.size();
  values = ctx_.values_at(x);
  std::vector<double> h;
  const std::vector<ParamValues> shifted =
      derivatives ? shifted_points(ctx_.vars, x, values, h) : std::vector<ParamValues>{};
  const std::vector<double> sums = ordered_reduce(ctx_.blocks.size(), 1 + nv + nv * nv, [&](size_t i, double* acc) {
    block_partials(i, values, shifted, h, derivatives, acc);
  });
  out.cost = sums[0];
  out.gradient = Eigen::VectorXd::Zero(Index(nv));
  out.jtj = Eigen::MatrixXd::Zero(Index(nv), Index(nv));
  if (!derivatives) return true;
  for (size_t u = 0; u < nv; ++u) {
    out.gradient[Index(u)] = sums[1 + u];
    for (size_t v = u; v < nv; ++v) out.jtj(Index(u), Index(v)) = sums[1 + nv + u * nv + v];
  }
  out.jtj = out.jtj.selfadjointView<Eigen::Upper>();
  return true;
}

}  // namespace brdfkit::fit
