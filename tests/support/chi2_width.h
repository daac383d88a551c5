#pragma once
// The negative control of the sampling χ² tests (tests/models/test_chi2.cpp): a sampler whose lobe
// is 5 % wider than the density it is checked against.
//
// Each model names the parameters that set its lobe width w and the power e with which each
// enters it (w ∝ xᵉ), so that x·f^{1/e} makes the lobe f times wider:
//   slope-space widths (α, m, σ of the distributions in ndf/):              e = 1
//   principled roughness r, α = r² (glTF 2.0 Appendix B, Burley 2012):      e = 2
//   pbrt-v4 roughness r, α = sqrt(r) (TrowbridgeReitzDistribution::RoughnessToAlpha): e = 1/2
//   cosine-power exponents N (cosᴺθ ≈ exp(−Nθ²/2): Phong, Blinn-Phong, Lafortune,
//     Ashikhmin-Shirley; Sawicki 2006's (1 + Nθ²/8)⁻⁴ near its peak):    e = −1/2
//   Löw's ABC sharpness B (1/(1 + B x²)^C, seed 003 Eq. 11):                e = −1/2
//   He's autocorrelation length τ (lobe α ∝ 1/τ, HeTorrance::lobe_alpha):  e = −1
// A Lambertian lobe has no width parameter; its control draws the cosine-power lobe cosᵏθ whose
// RMS sinθ is f times the cosine lobe's.
//
// The control runs on the model's lobe alone (power_values): a diffuse part drawn with the lobe
// only dilutes what a width error changes.
#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "brdfkit/core/param.h"
#include "brdfkit/core/sphere_integral.h"
#include "brdfkit/core/vec.h"
#include "brdfkit/models/model.h"

namespace brdfkit::test {

struct WidthParam {
  std::string_view name;
  double power;  // e in w ∝ xᵉ
};

struct PowerCase {
  std::string_view model;
  std::vector<WidthParam> width;                               // empty: a Lambertian lobe
  std::vector<std::pair<std::string_view, double>> set = {};  // values other than the defaults
  long draws = 100000;
  bool slow_sampler = false;  // ~1 ms a draw: run on request only (test_chi2.cpp)
};

// Draw counts: 10⁵ give every lobe here a p-value below 10⁻⁸ when 5 % wider, at θo = 30°
// (printed by the test). The Gaussian and Sawicki samplers rebuild their 8192-node θ CDF on every
// draw (CookTorrance::sample constructs the distribution, whose LazyThetaCdf is per object,
// ndf/theta_cdf.h): ~1 ms a draw, so they get the fewest draws that reject (p 3e-8 and 2e-10).
// Löw's defaults are sharper than the 20 × 40 grid resolves (B = 1000: |Dp| ≈ 0.03); B = 25 is
// the width of Ward's α = 0.1 (B x² = x²/(4α²) with x = |Dp| ≈ 2θh), and C = 3 gives the ABC
// facet a tail light enough that its core, where the width shows, holds most draws.
inline const std::vector<PowerCase>& power_cases() {
  static const std::vector<PowerCase> cases = {
      {"lambert", {}},
      {"cook-torrance", {{"alpha", 1}}},
      {"cook-torrance-beckmann", {{"alpha", 1}}},
      {"cook-torrance-blinn-phong", {{"N", -0.5}}},
      {"cook-torrance-gaussian", {{"m", 1}}, {}, 10000, true},
      {"cook-torrance-ggx", {{"alpha", 1}}},
      {"cook-torrance-gtr", {{"alpha", 1}}},
      {"cook-torrance-exponential", {{"alpha", 1}}},
      // SGD's α scales the slope in the power-law core and the squared slope in the exponential
      // tail (seed 000 §4.2): e = 1 widens the core by f and the tail by less.
      {"cook-torrance-sgd", {{"alpha", 1}}},
      {"cook-torrance-exponential-power", {{"sigma", 1}}},
      {"cook-torrance-schlick-rational", {{"m", 1}}},
      {"cook-torrance-sawicki-rational", {{"N", -0.5}}, {}, 30000, true},
      {"ward", {{"alpha", 1}}},
      {"ward-aniso", {{"alpha_x", 1}, {"alpha_y", 1}}},
      {"cook-torrance-beckmann-aniso", {{"alpha_x", 1}, {"alpha_y", 1}}, {{"alpha_y", 0.4}, {"phi_t", 0.6}}},
      {"cook-torrance-ggx-aniso", {{"alpha_x", 1}, {"alpha_y", 1}}, {{"alpha_y", 0.4}, {"phi_t", 0.6}}},
      {"poulin-fournier", {{"n", -0.5}}},
      {"ward-duer", {{"alpha", 1}}},
      {"blinn-phong", {{"N", -0.5}}},
      {"lafortune", {{"N", -0.5}}},
      {"lafortune-2", {{"N1", -0.5}, {"N2", -0.5}}},
      {"ashikhmin-shirley", {{"N", -0.5}}},
      {"ashikhmin-shirley-dielectric", {{"N", -0.5}}},
      {"ashikhmin-shirley-ngan2005", {{"N", -0.5}}},
      {"he", {{"tau", -1}}},
      {"low-smooth", {{"B", -0.5}}, {{"B", 25}}, 1000000},
      {"low-smooth-2", {{"B1", -0.5}, {"B2", -0.5}}, {{"B1", 25}, {"B2", 25}}, 1000000},
      {"low-microfacet", {{"B", -0.5}}, {{"C", 3}}},
      {"holzschuch-pacanowski", {{"sigma", 1}}},
      {"cook-torrance-low2012", {{"alpha", 1}}},
      {"cook-torrance-sgd-bagher2012", {{"alpha", 1}}},
      {"gltf-metallic-roughness", {{"roughness", 2}}},
      {"mitsuba-roughconductor-beckmann", {{"alpha", 1}}},
      {"mitsuba-roughconductor-ggx", {{"alpha", 1}}},
      {"mitsuba-principled", {{"roughness", 2}}},
      {"pbrt-conductor", {{"roughness", 0.5}}},
      {"pbrt-conductor-reflectance", {{"roughness", 0.5}}},
      {"pbrt-diffuse", {}},
      {"pbrt-mix-diffuse-conductor", {{"roughness", 0.5}}},
      {"disney-principled", {{"roughness", 2}}},
  };
  return cases;
}

inline const PowerCase* power_case(std::string_view model) {
  for (const PowerCase& c : power_cases())
    if (c.model == model) return &c;
  return nullptr;
}

inline void set_all_channels(const Model& m, ParamValues& v, std::string_view name, double x) {
  const int i = find_param(m.params(), std::string(name));
  if (i < 0) return;
  for (auto& ch : v.values) ch[size_t(i)] = x;
}

// The defaults with the lobe alone: diffuse weights (kd, and Holzschuch-Pacanowski's kw, whose
// diffraction lobe is drawn as a diffuse one) 0, principled models fully metallic, pbrt's mix all
// conductor; then the case's own values.
inline ParamValues power_values(const Model& m, const PowerCase& c) {
  ParamValues v = ParamValues::defaults(m.params());
  for (const char* name : {"kd", "kw"}) set_all_channels(m, v, name, 0.0);
  for (const char* name : {"metallic", "amount"}) set_all_channels(m, v, name, 1.0);
  for (const auto& [name, x] : c.set) set_all_channels(m, v, name, x);
  return v;
}

// v with every width parameter of `c` set so the lobe is `factor` times wider, in every channel.
inline ParamValues widened(const Model& m, const PowerCase& c, ParamValues v, double factor) {
  for (const WidthParam& w : c.width) {
    const int i = find_param(m.params(), std::string(w.name));
    for (auto& ch : v.values) ch[size_t(i)] *= std::pow(factor, 1 / w.power);
  }
  return v;
}

// Exponent k of the cosine-power lobe cosᵏθ whose RMS sinθ is `factor` times the cosine lobe's:
// E[sin²θ] = 2/(k + 3) under (k+1)/(2π) cosᵏθ, 1/2 for the cosine lobe (k = 1).
inline double widened_cosine_exponent(double factor) { return 4 / (factor * factor) - 3; }

// ∫ pdf dω over the upper hemisphere, cell by cell on the χ² test's (cosθ, φ) grid
// (analysis/chi2_test.h), so lobes narrower than a cell are integrated as accurately as there.
template <class Pdf> double hemisphere_integral(const Pdf& pdf, int cos_theta_cells = 20, int phi_cells = 40) {
  std::vector<double> c(size_t(cos_theta_cells) + 1), phi(size_t(phi_cells) + 1);
  for (int i = 0; i <= cos_theta_cells; ++i) c[size_t(i)] = double(i) / cos_theta_cells;
  for (int j = 0; j <= phi_cells; ++j) phi[size_t(j)] = -kPi + 2 * kPi * j / phi_cells;
  const auto f = [&](double ct, double ph) {
    const double st = std::sqrt(std::max(0.0, 1 - ct * ct));
    return pdf(Vec3d(st * std::cos(ph), st * std::sin(ph), ct));
  };
  return integrate_grid(f, c, phi, 1e-6, 8);
}

}  // namespace brdfkit::test
