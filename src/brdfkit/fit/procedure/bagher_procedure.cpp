// Bagher et al. 2012 (seed 000) §5, DESIGN.md §8 `bagher`: every channel on its own (§5.1),
// two slices of the data (§5.2):
//   1. θd = 0: fit ρh(θh) = ρd/π + Fr D(θh) G1²(θh)/(π cos²θh) (Eq. 12, uniform w_i) for ρd, Fr
//      and the distribution's shape — here the model itself with F ≡ 1 (F0 = 1, F1 = 0 in
//      Eq. 11), so its ks is Fr in brdfkit's units (ks = 4ρs/π, cook_torrance.h);
//   2. θh = 0, θd ≤ 70°: extract ks F(θd) = (m − ρd/π)/s(θd), s the lobe with ks = 1, F ≡ 1, and
//      fit Eq. 11 to it. Eq. 11 is linear in (ks F0, ks (1 − F0), ks F1), so the fit is a
//      linear least-squares solve, exact; F(π/2) = 1 holds by construction and gives ks = sum
//      of the first two (the paper's "using F_D(π/2) = 1, we get ρs, F0 and F1").
// The slices are taken at the centres of MERL's first θd row and first θh row (θd = 0.5°,
// θh = 0.003°, φd = 90.5°): the cells a MERL file actually has there; θh is sampled at the
// MERL θh cell centres, dense near the peak — what the paper wants from the slice (§5.2).
// The procedure is per channel by definition (§5.1), so FitSettings::per_channel_shape
// does not change it; a shared shape is what `--metric bagher` with the ngan procedure fits.
#include <ceres/ceres.h>
#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>

#include "brdfkit/core/dense_solver_options.h"
#include "brdfkit/core/error.h"
#include "brdfkit/fit/engine/random_start.h"
#include "brdfkit/fit/procedure/procedure_steps.h"
#include "brdfkit/measured/merl.h"

namespace brdfkit::fit {

namespace {

struct SlicePoint {
  Vec3d wi, wo;
  double measured;  // one channel
  double weight;    // 1/s(θd) in step 2, 1 in step 1
};

struct Layout {
  int kd = -1, ks = -1, f0 = -1, f1 = -1;
  std::vector<int> shape;  // every other parameter with room between its bounds
};

Layout layout_of(const Model& model) {
  const ParamTable& t = model.params();
  Layout l{find_param(t, "kd"), find_param(t, "ks"), find_param(t, "F0"), find_param(t, "F1"), {}};
  if (l.kd < 0 || l.ks < 0 || l.f0 < 0 || l.f1 < 0)
    throw InputError("model '" + std::string(model.name()) + "'",
                     "the bagher procedure needs parameters kd, ks and the Bagher Fresnel term F0, F1 "
                     "(seed 000 Eq. 11), e.g. cook-torrance-sgd-bagher2012");
  for (size_t i = 0; i < t.size(); ++i) {
    const int p = int(i);
    if (p == l.kd || p == l.ks || p == l.f0 || p == l.f1 || !(t[i].upper > t[i].lower)) continue;
    l.shape.push_back(p);
  }
  return l;
}

// Directions of the cell centres of one MERL row (θd index 0, or θh index 0) and the data there.
std::vector<std::pair<Vec3d, Vec3d>> slice_directions(bool theta_d_zero) {
  std::vector<std::pair<Vec3d, Vec3d>> out;
  const int n = theta_d_zero ? merl::kResThetaH : 70;  // θd ≤ 70° (DESIGN.md §8)
  for (int k = 0; k < n; ++k) {
    const merl::Cell cell = theta_d_zero ? merl::Cell{k, 0, merl::kResPhiD / 2} : merl::Cell{0, k, merl::kResPhiD / 2};
    Vec3d wi, wo;
    if (merl::cell_directions(cell, wi, wo)) out.push_back({wi, wo});
  }
  return out;
}

// Step 1 residual: √w (m − ρ) at the slice points, x = the free parameters of one channel.
struct SliceCost {
  const Model& model;
  int channel;
  std::vector<double> base;  // the channel's full parameter vector
  const std::vector<int>& free;
  const std::vector<SlicePoint>& points;
  bool operator()(double const* const* x, double* r) const {
    std::vector<double> p = base;
    for (size_t v = 0; v < free.size(); ++v) p[size_t(free[v])] = x[0][v];
    for (size_t k = 0; k < points.size(); ++k) {
      r[k] = points[k].weight * (points[k].measured - model.eval(p.data(), channel, points[k].wi, points[k].wo));
      if (!std::isfinite(r[k])) return false;
    }
    return true;
  }
};

struct StepResult {
  double cost = std::numeric_limits<double>::infinity();
  int iterations = 0;
  size_t cells = 0;
  bool converged = false;
  std::string message;
};

// Fits the `free` parameters of channel c to the points from settings.starts seeded starts.
StepResult fit_slice(const Model& model, int c, std::vector<double>& p, const std::vector<int>& free,
                     const std::vector<SlicePoint>& points, const FitSettings& settings) {
  const ParamTable& t = model.params();
  std::mt19937_64 rng(settings.seed + 1000003ull * std::uint64_t(c));
  StepResult best;
  std::vector<double> best_p = p;
  for (int start = 0; start < settings.starts; ++start) {
    std::vector<double> x(free.size());
    for (size_t v = 0; v < free.size(); ++v)
      x[v] = start == 0 ? p[size_t(free[v])] : random_start_value(t[size_t(free[v])], rng);
    auto* cost = new ceres::DynamicNumericDiffCostFunction<SliceCost, ceres::CENTRAL>(
        new SliceCost{model, c, p, free, points});
    cost->AddParameterBlock(int(free.size()));
    cost->SetNumResiduals(int(points.size()));
    ceres::Problem problem;
    problem.AddResidualBlock(cost, nullptr, x.data());
    for (size_t v = 0; v < free.size(); ++v) {
      problem.SetParameterLowerBound(x.data(), int(v), t[size_t(free[v])].lower);
      problem.SetParameterUpperBound(x.data(), int(v), t[size_t(free[v])].upper);
    }
    ceres::Solver::Summary summary;
    ceres::Solve(dense_solver_options(settings.max_iterations, {.function = 1e-14, .gradient = 1e-16, .parameter = 1e-12}),
                 &problem, &summary);
    best.iterations += int(summary.iterations.size()) - 1;
    if (!summary.IsSolutionUsable() || !std::isfinite(summary.final_cost)) continue;
    if (summary.final_cost < best.cost) {
      best.cost = summary.final_cost;
      best.converged = summary.termination_type == ceres::CONVERGENCE;
      best.message = summary.message;
      best_p = p;
      for (size_t v = 0; v < free.size(); ++v) best_p[size_t(free[v])] = x[v];
    }
  }
  p = best_p;
  return best;
}

// The two slices of the data, measured at their cells' centres.
struct Slices {
  std::vector<std::pair<Vec3d, Vec3d>> h = slice_directions(true), d = slice_directions(false);
  std::vector<std::optional<Rgb>> m_h, m_d;
  explicit Slices(const MeasuredBrdf& data) {
    for (const auto& [wi, wo] : h) m_h.push_back(data.eval(wi, wo));
    for (const auto& [wi, wo] : d) m_d.push_back(data.eval(wi, wo));
  }
};

// Step 1 (seed 000 Eq. 12) for channel c: kd, Fr (as ks with F ≡ 1) and the shape on the θd = 0
// slice. Fr at its bound means the slice's lobe may be negative: Eq. 11 gives F(0) = F0 − F1 < 0
// when F1 > F0, as published fits have (white-paint red: F(0.5°) = −1.2e-3, bagher_fresnel.h), so
// the slice is then also fitted with F ≡ −1 and the better fit kept. Leaves F ≡ 1 in p.
StepResult slice_step(const Model& model, const Layout& l, const Slices& sl, int c, std::vector<double>& p,
                      const FitSettings& settings, const Progress& progress, const std::string& file, double& sign) {
  const ParamTable& t = model.params();
  p[size_t(l.f0)] = 1.0;
  p[size_t(l.f1)] = 0.0;
  std::vector<SlicePoint> pts;
  for (size_t k = 0; k < sl.h.size(); ++k)
    if (sl.m_h[k]) pts.push_back({sl.h[k].first, sl.h[k].second, (*sl.m_h[k])[c], 1.0});
  std::vector<int> free = {l.kd, l.ks};
  free.insert(free.end(), l.shape.begin(), l.shape.end());
  if (pts.size() < free.size())
    throw MetricUndefined(file, fmt::format("the bagher procedure needs the θd = 0 slice; only {} of its {} cells are "
                                            "measured",
                                            pts.size(), sl.h.size()));
  if (progress) progress(fmt::format("bagher: channel {}: θd = 0 slice ({} cells)", c, pts.size()));
  const std::vector<double> start = p;
  StepResult s1 = fit_slice(model, c, p, free, pts, settings);
  sign = 1;
  if (!(p[size_t(l.ks)] > t[size_t(l.ks)].lower)) {
    std::vector<double> q = start;
    q[size_t(l.f0)] = -1.0;
    const StepResult negative = fit_slice(model, c, q, free, pts, settings);
    const int iterations = s1.iterations + negative.iterations;
    if (negative.cost < s1.cost) {
      s1 = negative;
      p = q;
      p[size_t(l.f0)] = 1.0;  // step 2 divides by the lobe with F ≡ 1
      sign = -1;
    }
    s1.iterations = iterations;
  }
  s1.cells = pts.size();
  if (!std::isfinite(s1.cost))
    throw FitError(fmt::format("bagher procedure: no start gave a finite fit of the θd = 0 slice (channel {})", c));
  return s1;
}

// Step 2 (seed 000 §5.2) for channel c: ks F(θd) = (m − kd/π)/s(θd) on the θh = 0 slice, Eq. 11 by
// linear least squares in (a, b, e) = (ks F0, ks (1 − F0), ks F1). p is left as it is when no
// positive specular scale fits the slice (ok false: step 1's lobe with F ≡ 1 is kept).
struct FresnelStep {
  size_t cells = 0;
  double ks = 0;
  bool ok = false;
};
FresnelStep fresnel_step(const Model& model, const Layout& l, const Slices& sl, int c, std::vector<double>& p,
                         const std::string& file) {
  std::vector<double> lobe = p, diffuse = p;
  lobe[size_t(l.kd)] = 0.0;
  lobe[size_t(l.ks)] = 1.0;
  diffuse[size_t(l.ks)] = 0.0;
  std::vector<double> rows_c, rows_y;
  for (size_t k = 0; k < sl.d.size(); ++k) {
    if (!sl.m_d[k]) continue;
    const auto& [wi, wo] = sl.d[k];
    const double s = model.eval(lobe.data(), c, wi, wo);
    if (!(s > 0) || !std::isfinite(s)) continue;
    const double y = ((*sl.m_d[k])[c] - model.eval(diffuse.data(), c, wi, wo)) / s;
    if (!std::isfinite(y)) continue;
    rows_c.push_back(wi.dot((wi + wo).normalized()));  // cos θd = wi·h
    rows_y.push_back(y);
  }
  if (rows_y.size() < 3)
    throw MetricUndefined(file, fmt::format("the bagher procedure needs the θh = 0 slice; only {} usable cells with "
                                            "θd ≤ 70°",
                                            rows_y.size()));
  Eigen::MatrixXd A(Eigen::Index(rows_y.size()), 3);
  Eigen::VectorXd y(Eigen::Index(rows_y.size()));
  for (size_t k = 0; k < rows_y.size(); ++k) {
    const double cd = rows_c[k], m5 = std::pow(1.0 - cd, 5);
    // ks F = ks F0 + ks (1 − F0) m⁵ − ks F1 cd, m = 1 − cd (seed 000 Eq. 11).
    A(Eigen::Index(k), 0) = 1.0;
    A(Eigen::Index(k), 1) = m5;
    A(Eigen::Index(k), 2) = -cd;
    y[Eigen::Index(k)] = rows_y[k];
  }
  const Eigen::Vector3d abe = A.colPivHouseholderQr().solve(y);
  const double ks = abe[0] + abe[1];  // F(π/2) = 1
  const ParamTable& t = model.params();
  const ParamSpec &sks = t[size_t(l.ks)], &sf0 = t[size_t(l.f0)], &sf1 = t[size_t(l.f1)];
  const FresnelStep out{rows_y.size(), ks, ks > sks.lower && std::isfinite(ks)};
  if (!out.ok) return out;
  p[size_t(l.ks)] = std::min(ks, sks.upper);
  p[size_t(l.f0)] = std::clamp(abe[0] / ks, sf0.lower, sf0.upper);
  p[size_t(l.f1)] = std::clamp(abe[2] / ks, sf1.lower, sf1.upper);
  return out;
}

}  // namespace

ProcedureResult bagher_procedure(const Model& model, MetricStore& store, const FitSettings& settings,
                                 const Progress& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  const MeasuredBrdf& data = store.data();
  const Layout l = layout_of(model);
  const ParamTable& t = model.params();
  ProcedureResult r;
  r.metric = settings.metric.empty() ? "bagher" : settings.metric;
  r.fit.values = ParamValues::defaults(t);
  const Slices slices(data);
  bool converged = true;
  for (int c = 0; c < 3; ++c) {
    std::vector<double>& p = r.fit.values.values[size_t(c)];
    double sign = 1;  // of F on the θd = 0 slice
    const StepResult s1 = slice_step(model, l, slices, c, p, settings, progress, data.path(), sign);
    r.fit.iterations += s1.iterations;
    converged = converged && s1.converged;
    std::string shape;
    for (int i : l.shape) shape += fmt::format(" {} = {:.6g}", t[size_t(i)].name, p[size_t(i)]);
    r.steps.push_back(fmt::format("channel {}: θd = 0 slice (seed 000 Eq. 12, {} cells): kd = {:.6g}, Fr = {:.6g},{}"
                                  " (cost {:.3g})",
                                  c, s1.cells, p[size_t(l.kd)], sign * p[size_t(l.ks)], shape, s1.cost));
    const FresnelStep s2 = fresnel_step(model, l, slices, c, p, data.path());
    if (!s2.ok) {
      converged = false;
      r.steps.push_back(fmt::format("channel {}: θh = 0 slice gave ks = {:.3g} ≤ 0; kept F ≡ 1 from step 1", c, s2.ks));
      continue;
    }
    r.steps.push_back(fmt::format("channel {}: θh = 0 slice (seed 000 Eq. 11, {} cells, θd ≤ 70°): ks = {:.6g}, "
                                  "F0 = {:.6g}, F1 = {:.6g}",
                                  c, s2.cells, p[size_t(l.ks)], p[size_t(l.f0)], p[size_t(l.f1)]));
  }
  r.fit.converged = converged;
  r.fit.message = converged ? "both slices converged in every channel" : "a slice fit did not converge";
  r.fit.metric_value = metric_value(r.metric, model, r.fit.values, store, settings.coarsen);
  r.fit.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.steps.push_back(fmt::format("{} = {:.6g}", r.metric, r.fit.metric_value));
  return r;
}

}  // namespace brdfkit::fit
