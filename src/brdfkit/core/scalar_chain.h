#pragma once
// Carrying derivatives through a function that is evaluated in doubles only (Boost special
// functions, quadratures): the caller computes the value and its partial derivatives at the
// scalar parts, and these helpers rebuild a ceres::Jet from them by the chain rule.
// Works for double (derivatives dropped) and for any Jet-like type with members `a` and `v`,
// so ndf/ headers need not include Ceres.
#include <type_traits>

namespace brdfkit {

template <class T> double value_of(const T& x) {
  if constexpr (std::is_arithmetic_v<T>)
    return static_cast<double>(x);
  else
    return value_of(x.a);
}

// f(x) with f = value, ∂f/∂x = d.
template <class T> T chain(double value, double d, const T& x) {
  if constexpr (std::is_arithmetic_v<T>) {
    return T(value);
  } else {
    T r(value);
    r.v = d * x.v;
    return r;
  }
}

// f(x1, x2) with partials d1, d2.
template <class T> T chain(double value, double d1, const T& x1, double d2, const T& x2) {
  if constexpr (std::is_arithmetic_v<T>) {
    return T(value);
  } else {
    T r(value);
    r.v = d1 * x1.v + d2 * x2.v;
    return r;
  }
}

}  // namespace brdfkit
