#pragma once
// Upper incomplete gamma Γ(s, x) = ∫ₓ^∞ t^{s−1} e^{−t} dt for s > −1, x > 0, with its partial
// derivatives, as SGD needs (seed 000 §4.2, DESIGN.md §3). Boost.Math's tgamma(s, x) needs s > 0;
// for −1 < s < 0 one step of Γ(s, x) = (Γ(s+1, x) − xˢ e⁻ˣ)/s, and s = 0 is E1(x) (DESIGN.md §3).
#include "brdfkit/core/scalar_chain.h"

namespace brdfkit {

// Γ(s, x) for s > −1, x > 0 (throws InputError outside).
double upper_gamma(double s, double x);
// ∂Γ/∂s = ∫ₓ^∞ ln t · t^{s−1} e^{−t} dt, by exp-sinh quadrature (no closed form).
double upper_gamma_ds(double s, double x);
// ∂Γ/∂x = −x^{s−1} e^{−x} (fundamental theorem of calculus).
double upper_gamma_dx(double s, double x);

// Γ(s, x) and, when ds is not null, ∂Γ/∂s, memoized per thread on the last (s, x): models
// construct their distribution at every evaluation with the same parameters.
double upper_gamma_cached(double s, double x, double* ds = nullptr);

// Γ(s, x) for double or ceres::Jet arguments.
template <class T> T upper_gamma(const T& s, const T& x) {
  const double sv = value_of(s), xv = value_of(x);
  if constexpr (std::is_arithmetic_v<T>) {
    return upper_gamma_cached(sv, xv);
  } else {
    double ds = 0.0;
    const double g = upper_gamma_cached(sv, xv, &ds);
    return chain(g, ds, s, upper_gamma_dx(sv, xv), x);
  }
}

}  // namespace brdfkit
