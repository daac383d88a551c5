#pragma once
// Bagher et al. 2012 Fresnel: F = F0 + (1 − F0)(1 − cos θd)⁵ − F1 cos θd (seed 000 Eq. 11;
// DESIGN.md §5). Evaluated as published: it goes negative near θd = 0 when F1 > F0 (3 of the
// 100 published fits, down to −0.07); the total BRDF stays positive through the diffuse term,
// and a fit that wants F ≥ 0 bounds F1 ≤ F0 itself.
#include "brdfkit/core/param.h"

namespace brdfkit {

template <class T> struct BagherFresnel {
  T f0;
  T f1;

  static ParamTable params() {
    // Published fits reach F0 = 6.06 and F1 = −0.71 (bagher2012-sgd.json): the bounds admit them.
    return {{"F0", -10.0, 10.0, 0.04, Scope::PerChannel, false, "Schlick term's normal reflectance (seed 000 Eq. 11, eta[0])"},
            {"F1", -10.0, 10.0, 0.0, Scope::PerChannel, false, "linear correction in cos(theta_d) (seed 000 Eq. 11, eta[1])"}};
  }
  explicit BagherFresnel(const T* p) : f0(p[0]), f1(p[1]) {}

  T eval(const T& cos_theta_d) const {
    const T c = cos_theta_d < T(0) ? T(0) : (cos_theta_d > T(1) ? T(1) : cos_theta_d);
    const T m = T(1) - c;
    const T m2 = m * m;
    return f0 + (T(1) - f0) * m2 * m2 * m - f1 * c;  // seed 000 Eq. 11
  }
};

}  // namespace brdfkit
