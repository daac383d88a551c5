// `he` against He, Torrance, Sillion & Greenberg 1991 (SIGGRAPH '91), the unpolarized isotropic
// model of its appendix, transcribed here (DESIGN.md §6):
//   ρ = kd/π + ks · F G S D / (π cosθi cosθr)                                  (Eq. 75; the
//       specular spike, a Dirac delta, has no value at a direction pair)
//   F  Fresnel reflectance of the complex index η + ik at the bisector, cos = |k̂r − k̂i|/2
//   G  = (v̂·v̂ / v̂z)², v̂ = k̂r − k̂i (Eq. 76; its polarization brackets equal |k̂i × k̂r|² each in
//      the unpolarized case and cancel the 1/|k̂i × k̂r|⁴)
//   S  = S(θi) S(θr), S(θ) = (1 − ½ erfc(a)) / (Λ(a) + 1), a = τ cotθ/(2σ0),
//      Λ(a) = ½ (e^{−a²}/(√π a) − erfc(a))                               (Eq. 23–25 with He's errata)
//   D  = π²τ²/(4λ²) Σ_{m≥1} e^{−g} gᵐ/(m!·m) exp(−τ² vxy²/(4m)), vxy = (2π/λ)|(k̂r − k̂i)xy|  (Eq. 78)
//   g  = ((2π/λ) σ (cosθi + cosθr))²                                            (Eq. 79)
//   σ  = σ0 / sqrt(1 + (z0/σ0)²), √(π/2) z0 = (σ0/4)(Ki + Kr) e^{−z0²/(2σ0²)},
//      K = tanθ erfc(τ/(2σ0 tanθ))                                               (Eq. 80–83)
// with λ = 0.645, 0.526, 0.444 µm for R, G, B (DESIGN.md §2). Here the series is summed term by
// term in log space until the terms past the Poisson mode fall below 1e-17 of the sum, and z0 is
// found by bisection. brdfkit truncates the series with a proven relative bound of 1e-6
// (models/he_series.h): that is this test's bound.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "brdfkit/models/model.h"
#include "reference_fresnel.h"
#include "reference_pairs.h"

namespace brdfkit::test::ref {
namespace {

constexpr double kLambdaUm[3] = {0.645, 0.526, 0.444};

double he_shadow(double cos_t, double sigma0, double tau) {
  if (!(cos_t < 1)) return 1.0;
  const double a = tau * cos_t / (2 * sigma0 * std::sqrt(1 - cos_t * cos_t));
  const double lambda = std::max(0.0, 0.5 * (std::exp(-a * a) / (std::sqrt(kPi) * a) - std::erfc(a)));
  return (1 - 0.5 * std::erfc(a)) / (lambda + 1);
}

double he_k(double cos_t, double sigma0, double tau) {
  if (!(cos_t < 1)) return 0.0;
  const double tan_t = std::sqrt(1 - cos_t * cos_t) / cos_t;
  return tan_t * std::erfc(tau / (2 * sigma0 * tan_t));
}

// σ of Eq. 80 with z0 of Eq. 81 by bisection on z0 ∈ [0, hi].
double he_sigma(double ci, double cr, double sigma0, double tau) {
  const double rhs_scale = sigma0 / 4 * (he_k(ci, sigma0, tau) + he_k(cr, sigma0, tau));
  auto f = [&](double z0) { return std::sqrt(kPi / 2) * z0 - rhs_scale * std::exp(-z0 * z0 / (2 * sigma0 * sigma0)); };
  double lo = 0, hi = std::max(rhs_scale, 1e-300);  // f(0) ≤ 0 ≤ f(rhs_scale/√(π/2)) ≤ f(hi)
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0 ? hi : lo) = mid;
  }
  const double z0 = 0.5 * (lo + hi);
  return sigma0 / std::sqrt(1 + sqr(z0 / sigma0));
}

double he_series(double g, double c) {
  if (!(g > 0)) return 0.0;
  double sum = 0;
  for (int m = 1; m < 100000; ++m) {
    const double t = std::exp(-g + m * std::log(g) - std::lgamma(m + 1.0) - std::log(double(m)) - c / m);
    sum += t;
    if (m > g + 10 && (t < 1e-17 * sum || m > 10 * (g + 100))) break;
  }
  return sum;
}

// The directional-diffuse term of Eq. 75 for channel c, without ks.
double he_directional_diffuse(const Vec3d& wi, const Vec3d& wr, double sigma0, double tau, double eta, double k, int c,
                              double norm = kPi) {
  const double lambda = kLambdaUm[c], wave = 2 * kPi / lambda;
  const Vec3d v = wi + wr;  // k̂r − k̂i with k̂i = −wi, the propagation direction of the incident light
  const double f = fresnel_complex(v.norm() / 2, eta, k);
  const double g_geom = sqr(v.squaredNorm() / v.z());
  const double s = he_shadow(wi.z(), sigma0, tau) * he_shadow(wr.z(), sigma0, tau);
  const double sigma = he_sigma(wi.z(), wr.z(), sigma0, tau);
  const double g = sqr(wave * sigma * (wi.z() + wr.z()));
  const double vxy2 = sqr(wave) * (v.x() * v.x() + v.y() * v.y());
  const double d = kPi * kPi * tau * tau / (4 * lambda * lambda) * he_series(g, tau * tau * vxy2 / 4);
  return f * g_geom * s * d / (norm * wi.z() * wr.z());
}

Reference he_reference(const Model& m, const ParamValues& v, double norm = kPi) {
  return [&m, v, norm](int c, const Vec3d& wi, const Vec3d& wo) {
    return param(m, v, "kd", c) / kPi +
           param(m, v, "ks", c) * he_directional_diffuse(wi, wo, param(m, v, "sigma0", c), param(m, v, "tau", c),
                                                         param(m, v, "eta", c), param(m, v, "k", c), c, norm);
  };
}

TEST(HeReference, DirectionalDiffuseTerm) {
  const Model& m = model_by_name("he");
  struct Surface { double sigma0, tau; const char* what; };
  // g at normal incidence (green): 0.3 (smooth: the first terms), 18 (medium), 440 (rough: many terms).
  for (Surface sf : {Surface{0.013, 0.8, "smooth"}, Surface{0.18, 3.0, "medium"}, Surface{0.9, 4.0, "rough"}}) {
    for (double k : {0.0, 3.0}) {  // dielectric, conductor
      const ParamValues v = values_of(m, {{"kd", 0.2, 0}, {"kd", 0.05, 1}, {"kd", 0.0, 2}, {"ks", 1.0, 0}, {"ks", 0.7, 1},
                                          {"ks", 1.3, 2}, {"sigma0", sf.sigma0}, {"tau", sf.tau}, {"eta", 1.5, 0},
                                          {"eta", 1.9, 1}, {"eta", 0.4, 2}, {"k", k}});
      const std::string label = std::string(sf.what) + (k > 0 ? " conductor" : " dielectric");
      expect_matches_reference(m, v, he_reference(m, v), 1e-6, label);
      expect_detects_five_percent(m, v, he_reference(m, v, kPi / 1.05), 1e-6, label);
    }
  }
}

}  // namespace
}  // namespace brdfkit::test::ref
