#include "brdfkit/analysis/backscatter.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include <ceres/ceres.h>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/alta_slice.h"
#include "brdfkit/core/registry.h"
#include "brdfkit/fit/engine/start_scan.h"
#include "brdfkit/ndf/distributions.h"
#include "brdfkit/shadowing/smith.h"

namespace brdfkit::analysis {

namespace {

// ρ on the slice, seed 000 Eq. 7 / 12 (the paper's ρs F(0) is Fr).
template <template <class> class Ndf, class T> T slice_model(const T* x, double cos_h) {
  const Ndf<T> ndf(x + 2);
  const T c(cos_h);
  const T g1 = smith_g1(ndf, c);
  return x[0] / T(kPi) + x[1] / T(kPi) * ndf.D(c) * g1 * g1 / (c * c);
}

// Value and derivatives finite: a shape parameter at its bound (SGD α → 0) gives finite ρ with
// infinite Jacobian, which Ceres reports on stderr unless the cost declines the point.
inline bool all_finite(double x) { return std::isfinite(x); }
template <class T, int N> bool all_finite(const ceres::Jet<T, N>& j) { return std::isfinite(j.a) && j.v.allFinite(); }

template <template <class> class Ndf> struct SliceResidual {
  double cos_h, m, sqrt_w;
  bool log_space;
  template <class T> bool operator()(T const* const* blocks, T* r) const {
    const T* x = blocks[0];
    const T rho = slice_model<Ndf>(x, cos_h);
    if (log_space) {
      using std::log;
      if (!(rho > T(0))) return false;
      r[0] = T(sqrt_w) * (log(rho) - T(std::log(m)));
    } else {
      r[0] = T(sqrt_w) * (rho - T(m));
    }
    return all_finite(r[0]);
  }
};

struct ChannelFit {
  std::vector<double> x;  // ρd, Fr, shape…
  double cost = INFINITY;
};

// Every fourth point of the start scan's grid of a parameter (fit/engine/start_scan.h).
std::vector<double> sparse_grid(const ParamSpec& spec) {
  const std::vector<double> g = fit::scan_grid(spec);
  std::vector<double> out;
  for (size_t k = g.size() / 8; k < g.size(); k += 4) out.push_back(g[k]);
  return out;
}

// Starting shapes: a deterministic grid over each parameter's useful range (seeded starts without
// randomness). The families of BackscatterOptions' default list have hand-placed grids; any other
// distribution gets the product of sparse scan grids of its (at most two) parameters.
std::vector<std::vector<double>> shape_starts(const std::string& family, const ParamTable& table) {
  const std::vector<double> widths = {0.02, 0.07, 0.2, 0.5};  // within these families' bounds
  std::vector<std::vector<double>> s;
  if (family == "sgd") {
    // α up to its bound 2: wide slices (pink-felt) want the flattest shapes; p up to near 2, the
    // GGX-like tail (α² + x)^−p.
    for (double a : {0.01, 0.05, 0.2, 0.6, 2.0})
      for (double p : {0.2, 1.0, 1.9}) s.push_back({a, p});
  } else if (family == "exponential-power") {
    for (double a : widths)
      for (double p : {0.5, 1.0, 2.0}) s.push_back({a, p});
  } else if (family == "beckmann" || family == "ggx" || family == "exponential") {
    for (double a : widths) s.push_back({a});
  } else {
    const std::vector<double> first = sparse_grid(table[0]);
    const std::vector<double> second = table.size() > 1 ? sparse_grid(table[1]) : std::vector<double>{0.0};
    for (double a : first)
      for (double b : second) s.push_back(table.size() > 1 ? std::vector<double>{a, b} : std::vector<double>{a});
  }
  return s;
}

// ρd and Fr enter linearly: for the shape in x[2…], their weighted least-squares values, written
// to x[0] and x[1].
template <template <class> class Ndf>
void linear_start(const BackscatterSlice& s, int c, bool log_space, std::vector<double>& x) {
  double aa = 0, ab = 0, bb = 0, ay = 0, by = 0;
  std::vector<double> unit = x;
  unit[0] = 0, unit[1] = kPi;
  for (size_t k = 0; k < s.theta_h.size(); ++k) {
    const double m = s.value[k][c];
    if (log_space && !(m > 0)) continue;
    const double w = s.weight[k] / (log_space ? m * m : 1.0);  // relative residuals approximate log ones
    const double a = kInvPi, b = slice_model<Ndf>(unit.data(), std::cos(s.theta_h[k]));
    aa += w * a * a, ab += w * a * b, bb += w * b * b, ay += w * a * m, by += w * b * m;
  }
  const double det = aa * bb - ab * ab;
  x[0] = det > 0 ? std::max(0.0, (ay * bb - by * ab) / det) : 0.0;
  x[1] = det > 0 ? std::max(1e-6, (by * aa - ay * ab) / det) : 1.0;
}

// Ceres from x (ρd, Fr, shape) on channel c of the slice; the final cost, or nothing when the
// channel has no value to fit.
template <template <class> class Ndf>
std::optional<double> solve_slice(const BackscatterSlice& s, int c, bool log_space, std::vector<double>& x) {
  const ParamTable table = Ndf<double>::params();
  ceres::Problem problem;
  for (size_t k = 0; k < s.theta_h.size(); ++k) {
    const double m = s.value[k][c];
    if (log_space && !(m > 0)) continue;
    using Cost = ceres::DynamicAutoDiffCostFunction<SliceResidual<Ndf>, 4>;
    auto* cost = new Cost(new SliceResidual<Ndf>{std::cos(s.theta_h[k]), m, std::sqrt(s.weight[k]), log_space});
    cost->AddParameterBlock(2 + int(table.size()));
    cost->SetNumResiduals(1);
    problem.AddResidualBlock(cost, nullptr, x.data());
  }
  if (problem.NumResidualBlocks() == 0) return std::nullopt;
  problem.SetParameterLowerBound(x.data(), 0, 0.0);
  problem.SetParameterUpperBound(x.data(), 0, 10.0);
  problem.SetParameterLowerBound(x.data(), 1, 0.0);
  problem.SetParameterUpperBound(x.data(), 1, 1e4);
  for (size_t i = 0; i < table.size(); ++i) {
    problem.SetParameterLowerBound(x.data(), 2 + int(i), table[i].lower);
    problem.SetParameterUpperBound(x.data(), 2 + int(i), table[i].upper);
  }
  ceres::Solver::Options o;
  o.max_num_iterations = 100;
  o.linear_solver_type = ceres::DENSE_QR;
  o.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(o, &problem, &summary);
  return summary.final_cost;
}

template <template <class> class Ndf>
ChannelFit fit_channel(const BackscatterSlice& s, int c, SliceFitSpace space, const std::string& family,
                       const std::vector<std::vector<double>>& seeded) {
  const bool log_space = space == SliceFitSpace::Log;
  std::vector<std::vector<double>> starts;
  for (const auto& shape : shape_starts(family, Ndf<double>::params())) {
    std::vector<double> x = {-1, -1};  // ρd, Fr: from the linear solve
    x.insert(x.end(), shape.begin(), shape.end());
    starts.push_back(x);
  }
  starts.insert(starts.end(), seeded.begin(), seeded.end());
  ChannelFit best;
  for (std::vector<double> x : starts) {
    if (x[0] < 0) linear_start<Ndf>(s, c, log_space, x);
    const std::optional<double> cost = solve_slice<Ndf>(s, c, log_space, x);
    if (!cost) break;
    if (std::isfinite(*cost) && *cost < best.cost) {
      best.cost = *cost;
      best.x = x;
    }
  }
  if (best.x.empty()) throw InputError("back-scattering slice", "no positive value to fit in channel " + std::to_string(c));
  return best;
}

template <template <class> class Ndf>
void fill_fit(const BackscatterSlice& s, SliceFitSpace space, BackscatterFit& f,
              const std::array<std::vector<std::vector<double>>, 3>& seeded = {}) {
  for (const auto& spec : Ndf<double>::params()) f.shape_names.push_back(spec.name);
  double mean_lin = 0, mean_log = 0;
  for (int c = 0; c < 3; ++c) {
    const ChannelFit cf = fit_channel<Ndf>(s, c, space, f.family, seeded[size_t(c)]);
    const double* x = cf.x.data();
    f.rho_d[size_t(c)] = x[0];
    f.fr[size_t(c)] = x[1];
    f.shape[size_t(c)].assign(cf.x.begin() + 2, cf.x.end());
    const Ndf<double> ndf(x + 2);
    double wsum = 0, lin = 0, wlog = 0, lg = 0, peak = 0;
    for (size_t k = 0; k < s.theta_h.size(); ++k) {
      const double ch = std::cos(s.theta_h[k]), m = s.value[k][c];
      const double rho = slice_model<Ndf>(x, ch), g1 = smith_g1(ndf, ch);
      f.model[size_t(c)].push_back(rho);
      f.fitted_d[size_t(c)].push_back(ndf.D(ch));
      // Eq. 7 solved for D with this family's ρd, Fr and G1.
      f.implied_d[size_t(c)].push_back(x[1] > 0 && g1 > 0 ? (m - x[0] * kInvPi) * kPi * ch * ch / (x[1] * g1 * g1) : 0.0);
      const double w = s.weight[k];
      wsum += w;
      lin += w * (m - rho) * (m - rho);
      peak = std::max(peak, m);
      if (m > 0 && rho > 0) {
        wlog += w;
        lg += w * std::pow(std::log(m) - std::log(rho), 2);
      }
    }
    f.error_linear[size_t(c)] = wsum > 0 && peak > 0 ? std::sqrt(lin / wsum) / peak : 0.0;
    f.error_log[size_t(c)] = wlog > 0 ? std::sqrt(lg / wlog) : 0.0;
    mean_lin += f.error_linear[size_t(c)] / 3;
    mean_log += f.error_log[size_t(c)] / 3;
  }
  f.mean_error_linear = mean_lin;
  f.mean_error_log = mean_log;
}

}  // namespace

BackscatterSlice backscatter_slice(const MeasuredBrdf& data, const BackscatterOptions& opt) {
  if (!(opt.max_theta_h_deg > 0 && opt.max_theta_h_deg < 90))
    throw SettingError("max_theta_h", "must be in (0, 90) degrees");
  if (opt.nodes < 4 || opt.nodes > 100000) throw InputError("back-scattering slice", "nodes must be in [4, 100000]");
  const double max_t = opt.max_theta_h_deg * kPi / 180;
  BackscatterSlice s;
  std::vector<double> theta;
  std::vector<Rgb> value;
  if (const auto* alta = dynamic_cast<const AltaSlice*>(&data)) {
    for (size_t k = 0; k < alta->cos_theta_h().size(); ++k) {
      const double t = std::acos(std::clamp(alta->cos_theta_h()[k], -1.0, 1.0));
      if (t <= max_t && alta->values()[k].allFinite()) theta.push_back(t), value.push_back(alta->values()[k]);
    }
  } else {
    for (int k = 0; k < opt.nodes; ++k) {
      const double u = (k + 0.5) / opt.nodes, t = u * u * kPi / 2;  // MERL's θh cell centres (DESIGN.md §2)
      if (t > max_t) break;
      const Vec3d w(std::sin(t), 0.0, std::cos(t));
      const auto m = data.eval(w, w);
      if (m && m->allFinite()) theta.push_back(t), value.push_back(*m);
    }
  }
  // Sort by angle (ALTA rows ascend in cos θh) and give each sample its band of half vectors.
  std::vector<size_t> order(theta.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return theta[a] < theta[b]; });
  for (size_t i : order) s.theta_h.push_back(theta[i]), s.value.push_back(value[i]);
  const size_t n = s.theta_h.size();
  if (n < 4)
    throw InputError(data.path(), "fewer than 4 values on the back-scattering slice wi = wo (scattered data such as "
                                  "Cornell files miss the retro-reflection neighbourhood)");
  for (size_t k = 0; k < n; ++k) {
    const double lo = k == 0 ? 0.0 : 0.5 * (s.theta_h[k - 1] + s.theta_h[k]);
    const double hi = k + 1 == n ? std::min(kPi / 2, s.theta_h[k] + 0.5 * (s.theta_h[k] - s.theta_h[k - 1]))
                                 : 0.5 * (s.theta_h[k] + s.theta_h[k + 1]);
    s.weight.push_back(2 * kPi * (std::cos(lo) - std::cos(hi)));
  }
  return s;
}

namespace {

// SGD contains Beckmann: with p = 0, K = 1/(α Γ(1, α)) = e^α/α and P22 = e^{−x/α}/(π α), Beckmann
// with m² = α (seed 000 §4.2, ndf/sgd.h). Starting SGD at the Beckmann optimum (ρd, Fr unchanged)
// makes its fit no worse than Beckmann's; the same α with p over a grid lets it leave p = 0,
// where the generic grid alone stopped on pink-felt (SGD error = Beckmann's, Fr = 0 in blue).
std::array<std::vector<std::vector<double>>, 3> sgd_seeds(const BackscatterSlice& slice, SliceFitSpace space,
                                                          const std::vector<BackscatterFit>& done) {
  const BackscatterFit* beck = nullptr;
  for (const auto& f : done)
    if (f.family == "beckmann") beck = &f;
  BackscatterFit own;
  if (!beck) {
    own.family = "beckmann";
    fill_fit<Beckmann>(slice, space, own);
    beck = &own;
  }
  std::array<std::vector<std::vector<double>>, 3> seeds;
  for (size_t c = 0; c < 3; ++c) {
    const double m = beck->shape[c][0];
    const double alpha = std::clamp(m * m, Sgd<double>::params()[0].lower, Sgd<double>::params()[0].upper);
    for (double p : {0.0, 0.5, 1.0, 1.5}) seeds[c].push_back({beck->rho_d[c], beck->fr[c], alpha, p});
  }
  return seeds;
}

using FamilyFit = void (*)(const BackscatterSlice&, SliceFitSpace, BackscatterFit&, const std::vector<BackscatterFit>&);

// Every distribution of ndf/distributions.h is a family.
const Registry<FamilyFit>& family_registry() {
  static const Registry<FamilyFit> registry = [] {
    Registry<FamilyFit> r("distribution family");
    Distributions::for_each([&]<template <class> class D>() {
      r.add(std::string(D<double>::kName), [](const BackscatterSlice& slice, SliceFitSpace space, BackscatterFit& f,
                                              const std::vector<BackscatterFit>& done) {
        if constexpr (std::is_same_v<D<double>, Sgd<double>>) fill_fit<D>(slice, space, f, sgd_seeds(slice, space, done));
        else fill_fit<D>(slice, space, f);
      });
    });
    return r;
  }();
  return registry;
}

}  // namespace

const std::vector<std::string>& backscatter_families() { return family_registry().names(); }

BackscatterAnalysis analyze_backscatter(const BackscatterSlice& slice, const BackscatterOptions& opt) {
  BackscatterAnalysis a;
  a.slice = slice;
  a.space = opt.space;
  for (const std::string& family : opt.families) {
    BackscatterFit f;
    f.family = family;
    family_registry().get(family)(slice, opt.space, f, a.fits);
    a.fits.push_back(std::move(f));
  }
  return a;
}

BackscatterAnalysis analyze_backscatter(const MeasuredBrdf& data, const BackscatterOptions& opt) {
  return analyze_backscatter(backscatter_slice(data, opt), opt);
}

}  // namespace brdfkit::analysis
