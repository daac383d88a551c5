#pragma once
// Shifted gamma distribution written inline for the shadowing tests, independent of ndf/sgd.h:
// P22(x) = α^{p−1}/Γ(1−p, α) · exp(−(α² + x)/α) / (α² + x)^p / π (seed 000 §4.2, DESIGN.md §3),
// with Γ(s, α) for s = 1 − p ≤ 0 by one step of Γ(s, x) = (Γ(s+1, x) − xˢ e⁻ˣ)/s and Γ(0, x) = E1(x).
// The normalization is a double (computed from the scalar parts). It has no SmithShape, so its Λ is
// the direct integral: the reference for ndf/sgd.h's table.
#include <boost/math/special_functions/expint.hpp>
#include <boost/math/special_functions/gamma.hpp>

#include <array>
#include <cmath>

#include "brdfkit/core/vec.h"
#include "brdfkit/shadowing/smith.h"

namespace brdfkit::test {

inline double upper_gamma(double s, double x) {
  if (s > 0) return boost::math::tgamma(s, x);
  if (s == 0) return boost::math::expint(1, x);
  return (boost::math::tgamma(s + 1, x) - std::pow(x, s) * std::exp(-x)) / s;  // s ∈ (−1, 0)
}

template <class T> struct TestSgd {
  T alpha, p;
  double norm;
  explicit TestSgd(const T* v) : alpha(v[0]), p(v[1]) {
    const double a = smith_detail::scalar(alpha), pp = smith_detail::scalar(p);
    norm = std::pow(a, pp - 1) / upper_gamma(1 - pp, a) / kPi;
  }
  T P22(const T& x) const {
    using std::exp;
    using std::pow;
    const T u = alpha * alpha + x;
    return T(norm) * exp(-u / alpha) / pow(u, p);
  }
  T Lambda(const T& tan_theta) const { return smith_lambda_numeric(*this, tan_theta); }
};

}  // namespace brdfkit::test

