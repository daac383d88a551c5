#pragma once
// D(θ) = P22(tan²θ)/cos⁴θ (seed 000 Eq. 2–3, DESIGN.md §3), read backwards: the slope-space
// form of a distribution that is defined by D(θ).
#include <cmath>

namespace brdfkit {

template <class Ndf, class T> T p22_from_d(const Ndf& ndf, const T& x) {
  using std::sqrt;
  const T c2 = T(1) / (T(1) + x);  // cos²θ with x = tan²θ
  return ndf.D(sqrt(c2)) * c2 * c2;
}

}  // namespace brdfkit
