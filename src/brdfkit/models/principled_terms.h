#pragma once
// Terms shared by the Burley-style "principled" models (models/mitsuba_principled.h,
// models/disney_principled.h): Schlick's weight, Burley's GTR1 and lerp, each as both sources
// write them (Mitsuba 3 v3.9.1 src/bsdfs/principledhelpers.h; wdas/brdf src/brdfs/disney.brdf).
#include <cmath>

#include "brdfkit/core/vec.h"

namespace brdfkit {

namespace principled_detail {

// (1 − cosθ)⁵ clamped (schlick_weight / Disney's SchlickFresnel).
template <class T> T schlick_weight(const T& c) {
  T m = T(1) - c;
  if (m < T(0)) m = T(0);
  if (m > T(1)) m = T(1);
  const T m2 = m * m;
  return m2 * m2 * m;
}
// Burley's GTR1 (γ = 1): (α² − 1) / (π ln α² (1 + (α² − 1) cos²θh)).
template <class T> T gtr1(const T& cos_h, const T& alpha) {
  using std::log;
  const T a2 = alpha * alpha;
  return (a2 - T(1)) / (T(kPi) * log(a2) * (T(1) + (a2 - T(1)) * cos_h * cos_h));
}
template <class T> T lerp(const T& a, const T& b, const T& t) { return a + t * (b - a); }

}  // namespace principled_detail

}  // namespace brdfkit
