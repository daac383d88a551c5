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
constexpr int kAzimuthSteps = 256;  // at least as many φm midpoints in the σ quadrature (max(0, ω·m) has a kink in φm)
using Rule = boost::math::quadrature::gauss<double, 4>;

// linear-sRGB luminance (IEC 61966-2-1's Y row), the `luminance` table the reader cross-checks.
double luminance(const Rgb& c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

// D or σ over the half-vector (or direction) unit square: `cols` nodes in u = sqrt(2θ/π), `rows`
// nodes in v = (φ + π)/2π, bilinear between them as the reader's NDF and σ interpolants. An
// isotropic table has two equal rows.
struct AngleTable {
  int cols = 0, rows = 2;
  bool isotropic = true;
  std::vector<double> v;  // [row][col]
  double& node(int row, int col) { return v[size_t(row) * size_t(cols) + size_t(col)]; }
  double at(double u, double w) const {
    auto cell = [](double x, int n) {
      const double t = std::clamp(x, 0.0, 1.0) * double(n - 1);
      const int j = std::min(int(t), n - 2);
      return std::pair{j, t - j};
    };
    const auto [c, fc] = cell(u, cols);
    const auto [r, fr] = cell(w, rows);
    auto node = [&](int rr, int cc) { return v[size_t(rr) * size_t(cols) + size_t(cc)]; };
    return (1 - fr) * ((1 - fc) * node(r, c) + fc * node(r, c + 1)) + fr * ((1 - fc) * node(r + 1, c) + fc * node(r + 1, c + 1));
  }
  // The direction of node (row, col); an isotropic table's rows are both asked at φ = 0.
  Vec3d direction(int row, int col) const {
    return spherical_direction(u2theta(double(col) / (cols - 1)), isotropic ? 0.0 : u2phi(double(row) / (rows - 1)));
  }
  // Sets every node to f(direction): once per column in an isotropic table.
  template <class F> void fill(F f) {
    tbb::parallel_for(0, isotropic ? 1 : rows, [&](int row) {
      for (int col = 0; col < cols; ++col) node(row, col) = f(direction(row, col));
    });
    if (isotropic) std::copy(v.begin(), v.begin() + cols, v.begin() + cols);
  }
  std::vector<float> as_floats() const { return std::vector<float>(v.begin(), v.end()); }
};

AngleTable empty_table(const RglWriteOptions& opt) {
  const bool isotropic = opt.phi_i == 1;
  const int rows = isotropic ? 2 : opt.ndf_azimuths;
  return AngleTable{opt.ndf_nodes, rows, isotropic, std::vector<double>(size_t(rows) * size_t(opt.ndf_nodes))};
}

// Quadrature points over the hemisphere of half vectors in (u, φ): Gauss in u on every table cell,
// midpoints in φ, as many in every φ cell of the table (exact for its bilinear D); weight =
// |dωm/du dv| du dv.
struct HalfVectorRule {
  std::vector<Vec3d> m;
  std::vector<double> u, v, weight;
  HalfVectorRule(int n, int rows) {
    const int cells = rows - 1, steps = cells * ((kAzimuthSteps + cells - 1) / cells);
    const auto& xs = Rule::abscissa();
    const auto& ws = Rule::weights();
    for (int j = 0; j + 1 < n; ++j)
      for (size_t i = 0; i < xs.size(); ++i)
        for (int side : {-1, 1}) {
          if (xs[i] == 0 && side > 0) continue;
          const double uu = (j + 0.5 + 0.5 * side * xs[i]) / (n - 1), wu = 0.5 * ws[i] / (n - 1);
          for (int k = 0; k < steps; ++k) {
            const double vv = (k + 0.5) / steps;
            m.push_back(spherical_direction(u2theta(uu), u2phi(vv)));
            u.push_back(uu);
            v.push_back(vv);
            weight.push_back(wu * half_vector_jacobian(uu) / steps);
          }
        }
  }
};

// D normalized to ∫ D cosθ dω = 1 over the rule.
void normalize(AngleTable& d, const HalfVectorRule& rule) {
  double mass = 0;
  for (size_t p = 0; p < rule.m.size(); ++p) mass += d.at(rule.u[p], rule.v[p]) * rule.m[p].z() * rule.weight[p];
  if (!(mass > 0)) throw InputError("rgl writer", "the retro-reflection is nowhere positive: no distribution to build");
  for (double& x : d.v) x /= mass;
}

// σ(ω) = ∫ D(m) max(0, ω·m) dωm at the table's node directions.
AngleTable projected_areas(const AngleTable& d, const HalfVectorRule& rule) {
  std::vector<double> dw(rule.m.size());
  for (size_t p = 0; p < dw.size(); ++p) dw[p] = d.at(rule.u[p], rule.v[p]) * rule.weight[p];
  AngleTable sigma = d;
  sigma.fill([&](const Vec3d& w) {
    double s = 0;
    for (size_t p = 0; p < dw.size(); ++p) s += std::max(0.0, w.dot(rule.m[p])) * dw[p];
    return s;
  });
  return sigma;
}

// Dupuy et al. 2015 ("Extracting microfacet-based BRDF parameters from arbitrary materials with
// power iterations"): D ∝ ρ(ω, ω) σ(ω)², starting from σ = 1.
AngleTable power_iteration_ndf(const RglSource& rho, const RglWriteOptions& opt, const HalfVectorRule& rule) {
  AngleTable retro = empty_table(opt);
  retro.fill([&](const Vec3d& node) {
    const double theta = rgl::elevation(node);
    const Vec3d w = spherical_direction(std::min(theta, kMaxEvalTheta), std::atan2(node.y(), node.x()));
    const auto v = rho(w, w);
    const double y = v ? luminance(*v) : 0.0;
    if (!std::isfinite(y))
      throw InputError("rgl writer", fmt::format("non-finite value at the retro-reflection θ = {:.2f}°, φ = {:.2f}°", theta * 180 / kPi,
                                                 std::atan2(w.y(), w.x()) * 180 / kPi));
    return std::max(0.0, y);
  });
  AngleTable d = retro;
  normalize(d, rule);
  for (int it = 0; it < opt.power_iterations; ++it) {
    const AngleTable sigma = projected_areas(d, rule);
    for (size_t k = 0; k < d.v.size(); ++k) d.v[k] = retro.v[k] * sigma.v[k] * sigma.v[k];
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

void check(const RglWriteOptions& o) {
  auto in = [](int x, int lo, int hi) { return x >= lo && x <= hi; };
  if (!in(o.theta_i, 2, 91)) throw InputError("rgl writer", "theta_i nodes must be in [2, 91]");
  if (!in(o.grid, 2, 512)) throw InputError("rgl writer", "grid must be in [2, 512]");
  if (!in(o.ndf_nodes, 8, 4096)) throw InputError("rgl writer", "ndf nodes must be in [8, 4096]");
  if (!in(o.vndf_nodes, 8, 1024)) throw InputError("rgl writer", "vndf nodes must be in [8, 1024]");
  if (!in(o.power_iterations, 0, 20)) throw InputError("rgl writer", "power iterations must be in [0, 20]");
  if (!in(o.phi_i, 1, 360) || o.phi_i == 2) throw InputError("rgl writer", "phi_i nodes must be 1 (isotropic) or in [3, 360]");
  if (o.symmetry != 1 && o.symmetry != 2 && o.symmetry != 4) throw InputError("rgl writer", "symmetry must be 1, 2 or 4");
  if (!in(o.ndf_azimuths, 3, 1024)) throw InputError("rgl writer", "ndf azimuths must be in [3, 1024]");
}

// The incidence nodes (φi, θi), slice = p · θi count + t as the reader indexes them. θi uniform in
// cosθi, as Dupuy & Jakob's measured files roughly are: dense towards the horizon, where ρ changes
// fastest with the incidence. φi uniform over the stored copy of the circle.
struct Incidence {
  std::vector<float> theta_i, phi_i;
  bool isotropic;
  explicit Incidence(const RglWriteOptions& o) : isotropic(o.phi_i == 1) {
    for (int t = 0; t < o.theta_i; ++t) theta_i.push_back(float(std::acos(1.0 - double(t) / (o.theta_i - 1))));
    if (isotropic) phi_i = {0.0f};
    for (int p = 0; !isotropic && p < o.phi_i; ++p)
      phi_i.push_back(float(-kPi + 2 * kPi / o.symmetry * double(p) / (o.phi_i - 1)));
    // Each node's own direction must fold to itself (measured/rgl_tensor.h): float(−π) lies below
    // −π, where sin φi > 0 would send it half a turn away; the last node of a half circle is −0,
    // whose sign bit keeps it where it is.
    if (!isotropic) phi_i.front() = std::nextafter(phi_i.front(), 0.0f);
    if (!isotropic && o.symmetry == 2) phi_i.back() = -0.0f;
  }
  size_t slices() const { return theta_i.size() * phi_i.size(); }
  double theta(size_t slice) const { return theta_i[slice % theta_i.size()]; }
  double phi(size_t slice) const { return phi_i[slice / theta_i.size()]; }
  // The half vector of the unit-square point u_m: its azimuth relative to φi in an isotropic file.
  Vec3d half_vector(size_t slice, const Vec2d& u_m) const {
    return spherical_direction(u2theta(u_m.x()), u2phi(u_m.y()) + (isotropic ? phi(slice) : 0.0));
  }
};

// The VNDF D(m) max(0, ωi·m) |dωm/du| of each incidence node on the half vector's unit square
// (x: u_θ, y: u_φ), nv × nv per node.
std::vector<float> vndf_table(const AngleTable& ndf, const Incidence& inc, int nv) {
  std::vector<float> vndf(inc.slices() * size_t(nv) * size_t(nv));
  tbb::parallel_for(size_t(0), inc.slices(), [&](size_t s) {
    const Vec3d wi = spherical_direction(inc.theta(s), inc.phi(s));
    for (int y = 0; y < nv; ++y)
      for (int x = 0; x < nv; ++x) {
        const Vec2d u(double(x) / (nv - 1), double(y) / (nv - 1));
        vndf[(s * size_t(nv) + size_t(y)) * size_t(nv) + size_t(x)] =
            float(ndf.at(u.x(), u.y()) * std::max(0.0, wi.dot(inc.half_vector(s, u))) * half_vector_jacobian(u.x()));
      }
  });
  return vndf;
}

// The reader's interpolants of the tables, so that the colour grid reads back exactly at its nodes.
struct Interpolants {
  MarginalWarp2D ndf, sigma, vndf;
};

struct ColourGrid {
  std::vector<float> rgb, luminance;  // [slice][3][y][x], [slice][y][x]
  std::vector<std::uint8_t> valid;    // [y][x]: measured and above the horizon at every slice
};

ColourGrid colour_grid(const RglSource& rho, const Interpolants& in, const Incidence& inc, int g) {
  const size_t ns = inc.slices(), cells = size_t(g) * size_t(g);
  ColourGrid out{std::vector<float>(ns * 3 * cells), std::vector<float>(ns * cells), {}};
  std::vector<std::uint8_t> measured(ns * cells, 1);
  tbb::parallel_for(size_t(0), ns, [&](size_t s) {
    const double th = inc.theta(s), ph = inc.phi(s), params[2] = {ph, th};
    const Vec3d wi = spherical_direction(th, ph), wi_eval = spherical_direction(std::min(th, kMaxEvalTheta), ph);
    const double sigma_i = in.sigma.eval(Vec2d(theta2u(th), phi2u(ph)));
    for (int y = 0; y < g; ++y)
      for (int x = 0; x < g; ++x) {
        const size_t cell = size_t(y) * size_t(g) + size_t(x);
        const Vec2d u_m = in.vndf.sample(Vec2d(double(x) / (g - 1), double(y) / (g - 1)), params).first;
        const Vec3d wo = reflect(wi, inc.half_vector(s, u_m)).normalized();
        const double d = in.ndf.eval(u_m);
        // The table holds ρ cosθo (times 4σ/D), which vanishes linearly at the horizon. A node whose
        // wo falls below it holds that quantity continued oddly (ρ of the mirror direction above
        // the horizon times the negative cosθo), so that interpolating towards the horizon follows
        // ρ cosθo → 0 and the reader's division by cosθo stays near ρ; with 0 stored there, ρ
        // within a cell of the horizon came out up to 100 times too large.
        const Vec3d above(wo.x(), wo.y(), std::abs(wo.z()));
        const std::optional<Rgb> v = d > 0 ? rho(wi_eval, above) : std::nullopt;
        if (!(wo.z() > 0) || !v) measured[s * cells + cell] = 0;
        if (v && !v->allFinite())
          throw InputError("rgl writer", fmt::format("non-finite value at θi = {:.2f}°, φi = {:.2f}°, wo = ({:.4f}, {:.4f}, {:.4f})",
                                                     th * 180 / kPi, ph * 180 / kPi, above.x(), above.y(), above.z()));
        const Rgb value = v ? Rgb(*v * (4 * sigma_i * wo.z() / d)) : Rgb::Zero();
        for (size_t c = 0; c < 3; ++c) out.rgb[(s * 3 + c) * cells + cell] = float(value[Eigen::Index(c)]);
        out.luminance[s * cells + cell] = float(std::max(0.0, luminance(value)));  // a sampling density: ≥ 0
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
  const HalfVectorRule rule(opt.ndf_nodes, empty_table(opt).rows);
  const AngleTable ndf = power_iteration_ndf(rho, opt, rule);
  const AngleTable sigma = projected_areas(ndf, rule);
  const Incidence inc(opt);
  const std::vector<float> vndf = vndf_table(ndf, inc, opt.vndf_nodes);
  const std::vector<float> ndf_f = ndf.as_floats(), sigma_f = sigma.as_floats();
  const Interpolants in{MarginalWarp2D(ndf_f.data(), ndf.cols, ndf.rows, {}, false),
                        MarginalWarp2D(sigma_f.data(), sigma.cols, sigma.rows, {}, false),
                        MarginalWarp2D(vndf.data(), opt.vndf_nodes, opt.vndf_nodes, {inc.phi_i, inc.theta_i}, true)};
  const ColourGrid grid = colour_grid(rho, in, inc, opt.grid);
  const std::vector<double> wl = spectrum_wavelengths();
  const std::uint64_t np = inc.phi_i.size(), nt = inc.theta_i.size(), nv = std::uint64_t(opt.vndf_nodes),
                      g = std::uint64_t(opt.grid), rows = std::uint64_t(ndf.rows), cols = std::uint64_t(ndf.cols), nl = wl.size();

  TensorFileWriter w;
  w.add_text("description", opt.description);
  w.add_f32("phi_i", {np}, inc.phi_i);
  w.add_f32("theta_i", {nt}, inc.theta_i);
  w.add_f32("sigma", {rows, cols}, sigma_f);
  w.add_f32("ndf", {rows, cols}, ndf_f);
  w.add_f32("vndf", {np, nt, nv, nv}, vndf);
  w.add_f32("luminance", {np, nt, g, g}, grid.luminance);
  if (opt.rgb_table) w.add_f32("rgb", {np, nt, 3, g, g}, grid.rgb);
  w.add_f32("wavelengths", {nl}, std::vector<float>(wl.begin(), wl.end()));
  w.add_f32("spectra", {np, nt, nl, g, g}, spectra_of(grid.rgb, np * nt, g * g, wl));
  w.add_u8("jacobian", {1}, {1});
  w.add_u8("valid", {g * g}, grid.valid);
  write_file_atomically(file, w.bytes());
}

}  // namespace brdfkit
