#pragma once
// The normal distributions of DESIGN.md §3, written out for the reference tests from the table
// there (seed 000 Table 1, seed 001 Table 1, seed 004 Table 1 and Eq. 19/26), independently of
// brdfkit's ndf/ code: each as its slope density P22(x), x = tan²θ, and D(θ) = P22(x)/cos⁴θ.
// test_cook_torrance_reference.cpp checks that every one integrates to ∫ D cosθ dω = 1, so a
// slip in this transcription cannot hide behind the same slip in brdfkit.
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/expint.hpp>
#include <boost/math/special_functions/gamma.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "brdfkit/core/vec.h"
#include "reference_math.h"

namespace brdfkit::test::ref {

struct RefNdf {
  std::string name;                 // brdfkit's distribution name (`cook-torrance-<name>`)
  std::vector<double> params;       // in brdfkit's parameter order (for values_of)
  std::vector<std::string> param_names;
  std::function<double(double)> p22;  // P22(x), x = tan²θ ≥ 0
  double x_max = std::numeric_limits<double>::infinity();  // support edge in x (compact support)

  double D(double cos_theta) const {
    if (!(cos_theta > 0)) return 0.0;
    const double c2 = cos_theta * cos_theta;
    const double x = (1 - c2) / c2;
    if (x > x_max) return 0.0;
    return p22(x) / (c2 * c2);
  }
};

// Γ(s, x) for s > −1 (DESIGN.md §3: one step of Γ(s, x) = (Γ(s+1, x) − xˢe⁻ˣ)/s below 0, E1 at 0).
inline double upper_gamma(double s, double x) {
  if (s > 0) return boost::math::tgamma(s, x);
  if (s == 0) return boost::math::expint(1, x);
  return (boost::math::tgamma(s + 1, x) - std::pow(x, s) * std::exp(-x)) / s;
}

inline RefNdf ref_beckmann(double a) {
  return {"beckmann", {a}, {"alpha"}, [a](double x) { return std::exp(-x / (a * a)) / (kPi * a * a); }};
}
inline RefNdf ref_ggx(double a) {
  return {"ggx", {a}, {"alpha"}, [a](double x) { return a * a / (kPi * sqr(a * a + x)); }};
}
// Seed 001 Table 1: D = (N+2)/(2π) cosᴺθ, so P22 = D cos⁴θ = (N+2)/(2π) (1+x)^{−(N+4)/2}.
inline RefNdf ref_blinn_phong(double n) {
  return {"blinn-phong", {n}, {"N"}, [n](double x) { return (n + 2) / (2 * kPi) * std::pow(1 + x, -(n + 4) / 2); }};
}
// Seed 001 Table 1: D ∝ exp(−θ²/m²), normalized here by Gauss-Kronrod quadrature of
// 2π ∫ exp(−θ²/m²) cosθ sinθ dθ over [0, π/2].
inline RefNdf ref_gaussian(double m) {
  const double mass = 2 * kPi *
                      boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
                          [m](double t) { return std::exp(-t * t / (m * m)) * std::cos(t) * std::sin(t); }, 0.0,
                          kPi / 2, 20, 1e-15);
  return {"gaussian", {m}, {"m"}, [m, mass](double x) {
            const double t = std::atan(std::sqrt(x));
            return std::exp(-t * t / (m * m)) / mass / sqr(1 + x);
          }};
}
// Seed 004 Table 1.
inline RefNdf ref_gtr(double a, double g) {
  const double a2 = a * a;
  if (g == 1.0) {
    const double c = (1 - a2) / (2 * kPi * std::log(1 / a));
    return {"gtr", {a, g}, {"alpha", "gamma"}, [c, a2](double x) { return c / ((1 + x) * (a2 + x)); }};
  }
  const double c = (g - 1) * (1 - a2) / (1 - std::pow(a, 2 * (g - 1)));
  return {"gtr", {a, g}, {"alpha", "gamma"}, [c, a, a2, g](double x) {
            return c * std::pow(a, 2 * (g - 1)) * std::pow(1 + x, g - 2) / (kPi * std::pow(a2 + x, g));
          }};
}
inline RefNdf ref_exponential(double a) {
  return {"exponential", {a}, {"alpha"}, [a](double x) { return std::exp(-std::sqrt(x / (a * a))) / (2 * kPi * a * a); }};
}
// Seed 000 §4.2 with its 1/π (DESIGN.md §3).
inline RefNdf ref_sgd(double a, double p) {
  const double k = std::pow(a, p - 1) / upper_gamma(1 - p, a);
  return {"sgd", {a, p}, {"alpha", "p"}, [k, a, p](double x) {
            return k * std::exp(-(a * a + x) / a) / std::pow(a * a + x, p) / kPi;
          }};
}
// Seed 004 Eq. 19/26 with x/σ² (DESIGN.md §3).
inline RefNdf ref_exponential_power(double s, double p) {
  const double c = p / (kPi * s * s * std::tgamma(1 / p));
  return {"exponential-power", {s, p}, {"sigma", "p"},
          [c, s, p](double x) { return c * std::exp(-std::pow(x / (s * s), p)); }};
}
// Seed 001 Table 1 (Schlick 1994c): D = m³ y / (π cosβ (m y² − y² + m²)²), y = cosβ + m − 1,
// defined for cosβ ∈ [1 − m, 1] only (zero outside).
inline RefNdf ref_schlick_rational(double m) {
  RefNdf d{"schlick-rational", {m}, {"m"}, [m](double x) {
             const double c = 1 / std::sqrt(1 + x), y = c + m - 1;
             if (!(y > 0)) return 0.0;
             return m * m * m * y / (kPi * c * sqr(m * y * y - y * y + m * m)) * c * c * c * c;
           }};
  if (m < 1) d.x_max = (1 - sqr(1 - m)) / sqr(1 - m);
  return d;
}
// Seed 001 Table 1 (DESIGN.md §3): 96(3+N) cosβ / (π ((1−N) cosβ + N + 3)⁴).
inline RefNdf ref_sawicki_rational(double n) {
  return {"sawicki-rational", {n}, {"N"}, [n](double x) {
            const double c = 1 / std::sqrt(1 + x);
            return 96 * (3 + n) * c / (kPi * std::pow((1 - n) * c + n + 3, 4)) * c * c * c * c;
          }};
}

}  // namespace brdfkit::test::ref
