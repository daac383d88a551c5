#pragma once
// Smith's Λ for any slope density P22 (seed 000 Eq. 6, seed 004 Eq. 4–7, DESIGN.md §4), by
// quadrature written for the tests, in its own variable (brdfkit integrates another form).
//
// DESIGN.md §4: Λ(θ) = ∫_{μ}^∞ (r/μ − 1) P2(r) dr, P2(r) = ∫ P22(r² + q²) dq, μ = cotθ. Over the
// slope plane (x, y) this is (1/μ) ∫∫_{x>μ} (x − μ) P22(x² + y²) dx dy. In polar coordinates
// (s, φ) the φ integral over |φ| < acos(μ/s) is 2(s sinφ₀ − μ φ₀); with t = sqrt(s² − μ²)
// (s ds = t dt, s sinφ₀ = t, φ₀ = atan(t/μ)):
//   Λ(θ) = (2/μ) ∫₀^∞ (t − μ atan(t/μ)) · t · P22(t² + μ²) dt.
// t − μ atan(t/μ) cancels for t ≪ μ: its series t (y²/3 − y⁴/5 + y⁶/7 − y⁸/9), y = t/μ, is
// used below y = 0.01 (truncation < 1e-20 relative).
#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>

#include <cmath>
#include <limits>

#include "brdfkit/core/vec.h"
#include "reference_ndf.h"

namespace brdfkit::test::ref {

inline double smith_kernel(double t, double mu) {
  const double y = t / mu;
  if (y < 0.01) {
    const double y2 = y * y;
    return t * y2 * (1.0 / 3 - y2 * (1.0 / 5 - y2 * (1.0 / 7 - y2 / 9)));
  }
  return t - mu * std::atan(y);
}

inline double smith_lambda_numeric(const RefNdf& d, double cos_theta) {
  if (!(cos_theta < 1)) return 0.0;
  const double mu = cos_theta / std::sqrt(1 - cos_theta * cos_theta);
  auto f = [&](double t) { return smith_kernel(t, mu) * t * d.p22(t * t + mu * mu); };
  double integral;
  if (std::isfinite(d.x_max)) {
    if (!(d.x_max > mu * mu)) return 0.0;
    boost::math::quadrature::tanh_sinh<double> q;
    integral = q.integrate(f, 0.0, std::sqrt(d.x_max - mu * mu), 1e-13);
  } else {
    boost::math::quadrature::exp_sinh<double> q;
    integral = q.integrate(f, 0.0, std::numeric_limits<double>::infinity(), 1e-13);
  }
  return 2 / mu * integral;
}
inline double smith_g1_numeric(const RefNdf& d, double cos_theta) { return 1 / (1 + smith_lambda_numeric(d, cos_theta)); }

// Closed forms (DESIGN.md §4): Beckmann with a = 1/(α tanθ), GGX.
inline double beckmann_lambda(double alpha, double cos_theta) {
  if (!(cos_theta < 1)) return 0.0;
  const double a = cos_theta / (alpha * std::sqrt(1 - cos_theta * cos_theta));
  return (std::erf(a) - 1) / 2 + std::exp(-a * a) / (2 * a * std::sqrt(kPi));
}
inline double ggx_lambda(double alpha, double cos_theta) {
  const double tan2 = (1 - cos_theta * cos_theta) / (cos_theta * cos_theta);
  return (std::sqrt(1 + alpha * alpha * tan2) - 1) / 2;
}

}  // namespace brdfkit::test::ref
