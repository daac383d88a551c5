#include "brdfkit/measured/rgl_writer.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <boost/math/quadrature/gauss.hpp>
#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "brdfkit/core/atomic_file.h"
#include "brdfkit/core/error.h"
#include "brdfkit/measured/marginal_warp_2d.h"
#include "brdfkit/measured/rgl_coordinates.h"
#include "brdfkit/measured/spectral_rgb.h"
#include "brdfkit/measured/tensor_file_writer.h"

namespace brdfkit {

namespace {

using rgl::half_vector_jacobian;
using rgl::phi2u;
using rgl::theta2u;
using rgl::u2phi;
using rgl::u2theta;

// The horizon node is evaluated just above it: ρ(wi, ·) of a source is 0 or undefined at θi = 90°.
constexpr double kMaxEvalTheta = 89.5 * kPi / 180;
constexpr int kAzimuthSteps = 256;  // φm midpoints of the σ quadrature (max(0, ω·m) has a kink in φm)
using Rule = boost::math::quadrature::gauss<double, 4>;

// linear-sRGB luminance (IEC 61966-2-1's Y row), the `luminance` table the reader cross-checks.
double luminance(const Rgb& c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

// A table over u = sqrt(2θ/π) ∈ [0, 1] at n uniform nodes, linear between them (as the reader's
// bilinear NDF and σ interpolants along a row).
struct UTable {
  std::vector<double> v;
  double at(double u) const {
    const double x = std::clamp(u, 0.0, 1.0) * double(v.size() - 1);
    const size_t j = std::min(size_t(x), v.size() - 2);
    return v[j] + (x - double(j)) * (v[j + 1] - v[j]);
  }
};

// Quadrature points over the hemisphere of half vectors in (u, φ): Gauss in u on every table cell,
// midpoints in φ; weight = |dωm/du dv| du dv.
struct HalfVectorRule {
  std::vector<Vec3d> m;
  std::vector<double> u, weight;
  explicit HalfVectorRule(int n) {
    const auto& xs = Rule::abscissa();
    const auto& ws = Rule::weights();
    for (int j = 0; j + 1 < n; ++j)
      for (size_t i = 0; i < xs.size(); ++i)
        for (int side : {-1, 1}) {
          if (xs[i] == 0 && side > 0) continue;
          const double uu = (j + 0.5 + 0.5 * side * xs[i]) / (n - 1), wu = 0.5 * ws[i] / (n - 1);
          for (int k = 0; k < kAzimuthSteps; ++k) {
            const double v = (k + 0.5) / kAzimuthSteps;
            m.push_back(spherical_direction(u2theta(uu), u2phi(v)));
            u.push_back(uu);
            weight.push_back(wu * half_vector_jacobian(uu) / kAzimuthSteps);
          }
        }
  }
};

// D normalized to ∫ D cosθ dω = 1 over the rule.
void normalize(UTable& d, const HalfVectorRule& rule) {
  double mass = 0;
  for (size_t p = 0; p < rule.m.size(); ++p) mass += d.at(rule.u[p]) * rule.m[p].z() * rule.weight[p];
  if (!(mass > 0)) throw InputError("rgl writer", "the retro-reflection is nowhere positive: no distribution to build");
  for (double& x : d.v) x /= mass;
}

// σ(ω) = ∫ D(m) max(0, ω·m) dωm at the table's node directions (φ = 0).
UTable projected_areas(const UTable& d, const HalfVectorRule& rule) {
  const size_t n = d.v.size();
  std::vector<double> dw(rule.m.size());
  for (size_t p = 0; p < dw.size(); ++p) dw[p] = d.at(rule.u[p]) * rule.weight[p];
  UTable sigma{std::vector<double>(n)};
  tbb::parallel_for(size_t(0), n, [&](size_t k) {
    const Vec3d w = spherical_direction(u2theta(double(k) / double(n - 1)), 0.0);
    double s = 0;
    for (size_t p = 0; p < dw.size(); ++p) s += std::max(0.0, w.dot(rule.m[p])) * dw[p];
    sigma.v[k] = s;
  });
  return sigma;
}

// Dupuy et al. 2015 ("Extracting microfacet-based BRDF parameters from arbitrary materials with
// power iterations"): D ∝ ρ(ω, ω) σ(ω)², starting from σ = 1.
UTable power_iteration_ndf(const RglSource& rho, const RglWriteOptions& opt, const HalfVectorRule& rule) {
  const int n = opt.ndf_nodes;
  std::vector<double> retro(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) {
    const Vec3d w = spherical_direction(std::min(u2theta(double(k) / (n - 1)), kMaxEvalTheta), 0.0);
    const auto v = rho(w, w);
    const double y = v ? luminance(*v) : 0.0;
    if (!std::isfinite(y))
      throw InputError("rgl writer", fmt::format("non-finite value at the retro-reflection θ = {:.2f}°", u2theta(double(k) / (n - 1)) * 180 / kPi));
    retro[size_t(k)] = std::max(0.0, y);
  }
  UTable d{retro};
  normalize(d, rule);
  for (int it = 0; it < opt.power_iterations; ++it) {
    const UTable sigma = projected_areas(d, rule);
    for (int k = 0; k < n; ++k) d.v[size_t(k)] = retro[size_t(k)] * sigma.v[size_t(k)] * sigma.v[size_t(k)];
    normalize(d, rule);
  }
  return d;
}

// The wavelengths of the `spectra` table, nm: the smoothest spectra need no finer steps.
std::vector<double> spectrum_wavelengths() {
  std::vector<double> wl;
  for (int l = 380; l <= 780; l += 20) wl.push_back(l);
  return wl;
}

// s = B rgb, the spectrum of least curvature ‖D s‖² (D: second differences, with a 10⁻⁶ ridge)
// whose colour is rgb: B = P⁻¹Mᵀ(M P⁻¹ Mᵀ)⁻¹, P = DᵀD + 10⁻⁶ I, M the reader's spectrum → RGB
// matrix, so M B = I (Lagrange conditions of the constrained least squares).
Eigen::MatrixXd rgb_to_spectrum(const std::vector<double>& wl) {
  const Eigen::Index n = Eigen::Index(wl.size());
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(n - 2, n);
  for (Eigen::Index i = 0; i + 2 < n; ++i) d(i, i) = 1, d(i, i + 1) = -2, d(i, i + 2) = 1;
  const Eigen::MatrixXd p = d.transpose() * d + 1e-6 * Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd m = default_spectrum_to_rgb().matrix(wl);
  const Eigen::MatrixXd pinv_mt = p.ldlt().solve(m.transpose());
  return pinv_mt * (m * pinv_mt).inverse();
}

// Both φ rows of an isotropic table.
std::vector<float> two_rows(const UTable& t) {
  std::vector<float> out;
  for (int row = 0; row < 2; ++row)
    for (double x : t.v) out.push_back(float(x));
  return out;
}

void check(const RglWriteOptions& o) {
  auto in = [](int x, int lo, int hi) { return x >= lo && x <= hi; };
  if (!in(o.theta_i, 2, 91)) throw InputError("rgl writer", "theta_i nodes must be in [2, 91]");
  if (!in(o.grid, 2, 512)) throw InputError("rgl writer", "grid must be in [2, 512]");
  if (!in(o.ndf_nodes, 8, 4096)) throw InputError("rgl writer", "ndf nodes must be in [8, 4096]");
  if (!in(o.vndf_nodes, 8, 1024)) throw InputError("rgl writer", "vndf nodes must be in [8, 1024]");
  if (!in(o.power_iterations, 0, 20)) throw InputError("rgl writer", "power iterations must be in [0, 20]");
}

// Incidence nodes uniform in cosθi, as Dupuy & Jakob's measured files roughly are: dense towards
// the horizon, where ρ changes fastest with the incidence.
std::vector<float> incidence_nodes(int nt) {
  std::vector<float> theta_i(static_cast<size_t>(nt));
  for (int t = 0; t < nt; ++t) theta_i[size_t(t)] = float(std::acos(1.0 - double(t) / (nt - 1)));
  return theta_i;
}

// The VNDF D(m) max(0, ωi·m) |dωm/du| of each incidence node on the half vector's unit square
// (x: u_θ, y: u_φ), nv × nv per node.
std::vector<float> vndf_table(const UTable& ndf, const std::vector<float>& theta_i, int nv) {
  std::vector<float> vndf(theta_i.size() * size_t(nv) * size_t(nv));
  tbb::parallel_for(size_t(0), theta_i.size(), [&](size_t t) {
    const Vec3d wi = spherical_direction(double(theta_i[t]), 0.0);
    for (int y = 0; y < nv; ++y)
      for (int x = 0; x < nv; ++x) {
        const double ux = double(x) / (nv - 1), uy = double(y) / (nv - 1);
        const Vec3d m = spherical_direction(u2theta(ux), u2phi(uy));
        vndf[(t * size_t(nv) + size_t(y)) * size_t(nv) + size_t(x)] =
            float(ndf.at(ux) * std::max(0.0, wi.dot(m)) * half_vector_jacobian(ux));
      }
  });
  return vndf;
}

// The reader's interpolants of the tables, so that the colour grid reads back exactly at its nodes.
struct Interpolants {
  MarginalWarp2D ndf, sigma, vndf;
};

struct ColourGrid {
  std::vector<float> rgb, luminance;  // [θi][3][y][x], [θi][y][x]
  std::vector<std::uint8_t> valid;    // [y][x]: measured and above the horizon at every θi
};

ColourGrid colour_grid(const RglSource& rho, const Interpolants& in, const std::vector<float>& theta_i, int g) {
  const size_t nt = theta_i.size(), cells = size_t(g) * size_t(g);
  ColourGrid out{std::vector<float>(nt * 3 * cells), std::vector<float>(nt * cells), {}};
  std::vector<std::uint8_t> measured(nt * cells, 1);
  tbb::parallel_for(size_t(0), nt, [&](size_t t) {
    const double th = theta_i[t], params[2] = {0.0, th};
    const Vec3d wi = spherical_direction(th, 0.0), wi_eval = spherical_direction(std::min(th, kMaxEvalTheta), 0.0);
    const double sigma_i = in.sigma.eval(Vec2d(theta2u(th), phi2u(0.0)));
    for (int y = 0; y < g; ++y)
      for (int x = 0; x < g; ++x) {
        const size_t cell = size_t(y) * size_t(g) + size_t(x);
        const Vec2d u_m = in.vndf.sample(Vec2d(double(x) / (g - 1), double(y) / (g - 1)), params).first;
        const Vec3d wo = reflect(wi, spherical_direction(u2theta(u_m.x()), u2phi(u_m.y()))).normalized();
        const double d = in.ndf.eval(u_m);
        // The table holds ρ cosθo (times 4σ/D), which vanishes linearly at the horizon. A node whose
        // wo falls below it holds that quantity continued oddly (ρ of the mirror direction above
        // the horizon times the negative cosθo), so that interpolating towards the horizon follows
        // ρ cosθo → 0 and the reader's division by cosθo stays near ρ; with 0 stored there, ρ
        // within a cell of the horizon came out up to 100 times too large.
        const Vec3d above(wo.x(), wo.y(), std::abs(wo.z()));
        const std::optional<Rgb> v = d > 0 ? rho(wi_eval, above) : std::nullopt;
        if (!(wo.z() > 0) || !v) measured[t * cells + cell] = 0;
        if (v && !v->allFinite())
          throw InputError("rgl writer", fmt::format("non-finite value at θi = {:.2f}°, wo = ({:.4f}, {:.4f}, {:.4f})",
                                                     th * 180 / kPi, above.x(), above.y(), above.z()));
        const Rgb value = v ? Rgb(*v * (4 * sigma_i * wo.z() / d)) : Rgb::Zero();
        for (size_t c = 0; c < 3; ++c) out.rgb[(t * 3 + c) * cells + cell] = float(value[Eigen::Index(c)]);
        out.luminance[t * cells + cell] = float(std::max(0.0, luminance(value)));  // a sampling density: ≥ 0
      }
  });
  out.valid.assign(cells, 1);
  for (size_t k = 0; k < measured.size(); ++k) out.valid[k % cells] &= measured[k];
  return out;
}

// The colour grid as spectra over `wl` (rgb_to_spectrum), [θi][λ][y][x].
std::vector<float> spectra_of(const std::vector<float>& rgb, size_t nt, size_t cells, const std::vector<double>& wl) {
  const Eigen::MatrixXd to_spectrum = rgb_to_spectrum(wl);
  const size_t nl = wl.size();
  std::vector<float> spectra(nt * nl * cells);
  for (size_t t = 0; t < nt; ++t)
    for (size_t cell = 0; cell < cells; ++cell) {
      const Eigen::Vector3d c(rgb[(t * 3 + 0) * cells + cell], rgb[(t * 3 + 1) * cells + cell],
                              rgb[(t * 3 + 2) * cells + cell]);
      const Eigen::VectorXd s = to_spectrum * c;
      for (size_t l = 0; l < nl; ++l) spectra[(t * nl + l) * cells + cell] = float(s[Eigen::Index(l)]);
    }
  return spectra;
}

}  // namespace

void write_rgl(const std::filesystem::path& file, const RglSource& rho, const RglWriteOptions& opt) {
  check(opt);
  const HalfVectorRule rule(opt.ndf_nodes);
  const UTable ndf = power_iteration_ndf(rho, opt, rule);
  const UTable sigma = projected_areas(ndf, rule);
  const std::vector<float> theta_i = incidence_nodes(opt.theta_i);
  const std::vector<float> vndf = vndf_table(ndf, theta_i, opt.vndf_nodes);
  const std::vector<float> ndf_rows = two_rows(ndf), sigma_rows = two_rows(sigma);
  const Interpolants in{MarginalWarp2D(ndf_rows.data(), opt.ndf_nodes, 2, {}, false),
                        MarginalWarp2D(sigma_rows.data(), opt.ndf_nodes, 2, {}, false),
                        MarginalWarp2D(vndf.data(), opt.vndf_nodes, opt.vndf_nodes, {{0.0f}, theta_i}, true)};
  const ColourGrid grid = colour_grid(rho, in, theta_i, opt.grid);
  const std::vector<double> wl = spectrum_wavelengths();
  const std::uint64_t nt = theta_i.size(), nv = std::uint64_t(opt.vndf_nodes), g = std::uint64_t(opt.grid),
                      nn = std::uint64_t(opt.ndf_nodes), nl = wl.size();

  TensorFileWriter w;
  w.add_text("description", opt.description);
  w.add_f32("phi_i", {1}, {0.0f});
  w.add_f32("theta_i", {nt}, theta_i);
  w.add_f32("sigma", {2, nn}, sigma_rows);
  w.add_f32("ndf", {2, nn}, ndf_rows);
  w.add_f32("vndf", {1, nt, nv, nv}, vndf);
  w.add_f32("luminance", {1, nt, g, g}, grid.luminance);
  if (opt.rgb_table) w.add_f32("rgb", {1, nt, 3, g, g}, grid.rgb);
  w.add_f32("wavelengths", {nl}, std::vector<float>(wl.begin(), wl.end()));
  w.add_f32("spectra", {1, nt, nl, g, g}, spectra_of(grid.rgb, nt, g * g, wl));
  w.add_u8("jacobian", {1}, {1});
  w.add_u8("valid", {g * g}, grid.valid);
  write_file_atomically(file, w.bytes());
}

}  // namespace brdfkit
