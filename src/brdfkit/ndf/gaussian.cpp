#include "brdfkit/ndf/gaussian.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>

namespace brdfkit {

namespace {
// e^{−θ²/m²} < 1e-43 beyond 10 m: the integrals stop there (or at π/2).
double upper_limit(double m) { return std::min(kPi / 2, 10.0 * m); }
}  // namespace

double gaussian_ndf_integral(double m, double* dI_dm) {
  thread_local double last_m = -1.0, last_I = 0.0, last_dI = 0.0;
  if (m != last_m) {
    using boost::math::quadrature::gauss_kronrod;
    const double b = upper_limit(m), m2 = m * m;
    last_I = gauss_kronrod<double, 61>::integrate(
        [m2](double t) { return std::exp(-t * t / m2) * std::cos(t) * std::sin(t); }, 0.0, b, 15, 1e-14);
    last_dI = gauss_kronrod<double, 61>::integrate(
        [m, m2](double t) { return std::exp(-t * t / m2) * (2 * t * t / (m2 * m)) * std::cos(t) * std::sin(t); }, 0.0, b,
        15, 1e-14);
    last_m = m;
  }
  if (dI_dm) *dI_dm = last_dI;
  return last_I;
}

ThetaCdf gaussian_ndf_cdf(double m) {
  const Gaussian<double> g(&m);
  return theta_cdf_of(g, upper_limit(m));
}

}  // namespace brdfkit
