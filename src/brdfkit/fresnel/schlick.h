#pragma once
// Schlick's Fresnel approximation F = F0 + (1 − F0)(1 − cos θd)⁵ (Schlick 1994; DESIGN.md §5).
#include "brdfkit/core/param.h"

namespace brdfkit {

template <class T> struct SchlickFresnel {
  T f0;  // reflectance at normal incidence

  static ParamTable params() {
    return {{"F0", 0.0, 1.0, 0.04, Scope::PerChannel, false, "Fresnel reflectance at normal incidence (Schlick 1994)"}};
  }
  explicit SchlickFresnel(const T* p) : f0(p[0]) {}

  // cos θd outside [0, 1] is clamped so a grazing round-off never gives a value above 1.
  T eval(const T& cos_theta_d) const {
    const T c = cos_theta_d < T(0) ? T(0) : (cos_theta_d > T(1) ? T(1) : cos_theta_d);
    const T m = T(1) - c;
    const T m2 = m * m;
    return f0 + (T(1) - f0) * m2 * m2 * m;  // DESIGN.md §5
  }
};

}  // namespace brdfkit
