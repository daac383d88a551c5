#include "brdfkit/core/upper_gamma.h"

#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/special_functions/expint.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "brdfkit/core/error.h"

namespace brdfkit {

namespace {

void check_domain(double s, double x) {
  if (!(s > -1.0) || !std::isfinite(s))
    throw InputError("upper_gamma", "order s = " + std::to_string(s) + " must be > -1 (SGD needs p < 2)");
  if (!(x > 0.0) || !std::isfinite(x))
    throw InputError("upper_gamma", "argument x = " + std::to_string(x) + " must be > 0");
}

// Below this |s| the recurrence loses more than ~1e-11 to cancellation (Γ(s+1,x) ≈ xˢe⁻ˣ):
// use the first-order expansion around s = 0 instead, whose error is O(s²).
constexpr double kSmallOrder = 1e-4;

// ∫ₓ^∞ lnᵏt · t^{s−1} e^{−t} dt = ∂ᵏΓ/∂sᵏ. t = x eʸ removes the steep t^{s−1} near t = x:
// ∫₀^∞ lnᵏt · tˢ e^{−t} dy, smooth and double-exponentially decaying, for exp-sinh quadrature.
double log_moment(int k, double s, double x) {
  auto f = [k, s, x](double y) {
    const double t = x * std::exp(y);
    if (t > 800.0) return 0.0;
    return std::pow(std::log(t), k) * std::pow(t, s) * std::exp(-t);
  };
  boost::math::quadrature::exp_sinh<double> integrator;
  return integrator.integrate(f, 0.0, std::numeric_limits<double>::infinity(), 1e-13);
}

}  // namespace

double upper_gamma(double s, double x) {
  check_domain(s, x);
  if (s > 0.0) return boost::math::tgamma(s, x);
  if (s == 0.0) return boost::math::expint(1, x);  // Γ(0, x) = E1(x)
  if (s > -kSmallOrder)  // Taylor series about s = 0, error O(s³)
    return boost::math::expint(1, x) + s * log_moment(1, 0.0, x) + 0.5 * s * s * log_moment(2, 0.0, x);
  // Recurrence Γ(s, x) = (Γ(s+1, x) − xˢ e⁻ˣ)/s (DESIGN.md §3); s + 1 > 0 here.
  return (boost::math::tgamma(s + 1.0, x) - std::pow(x, s) * std::exp(-x)) / s;
}

double upper_gamma_ds(double s, double x) {
  check_domain(s, x);
  return log_moment(1, s, x);
}

double upper_gamma_cached(double s, double x, double* ds) {
  thread_local double last_s = NAN, last_x = NAN, last_value = 0.0, last_ds = NAN;
  if (!(s == last_s && x == last_x)) {
    last_value = upper_gamma(s, x);
    last_s = s, last_x = x, last_ds = NAN;
  }
  if (ds) {
    if (std::isnan(last_ds)) last_ds = upper_gamma_ds(s, x);
    *ds = last_ds;
  }
  return last_value;
}

double upper_gamma_dx(double s, double x) {
  check_domain(s, x);
  return -std::pow(x, s - 1.0) * std::exp(-x);
}

}  // namespace brdfkit
