#pragma once
// Unpolarized Fresnel reflectance of a dielectric with relative index η, in the form of
// Cook & Torrance 1982 (their Eq. for F; DESIGN.md §5): c = cos θd, g² = η² + c² − 1,
// F = ½ (g−c)²/(g+c)² · (1 + (c(g+c) − 1)²/(c(g−c) + 1)²).
// It equals the mean of the s and p reflectances of Snell/Fresnel exactly (tests check it).
// η is per channel (dispersion); a paper that publishes one η (Löw 2012) sets all three.
#include <cmath>

#include "brdfkit/core/param.h"

namespace brdfkit {

template <class T> struct DielectricFresnel {
  T eta;  // relative index of refraction (inside / outside)

  static ParamTable params() {
    // Löw 2012's published fits span η ∈ [1.03, 99.99996] (published-fits/low2012-*.json).
    return {{"eta", 1.0, 100.0, 1.5, Scope::PerChannel, false,
             "relative index of refraction (Cook-Torrance 1982 dielectric Fresnel)"}};
  }
  explicit DielectricFresnel(const T* p) : eta(p[0]) {}

  T eval(const T& cos_theta_d) const {
    using std::sqrt;
    const T c = cos_theta_d > T(1) ? T(1) : cos_theta_d;
    // Grazing incidence reflects everything; it also avoids 0/0 at η = 1, c = 0.
    if (!(c > T(0))) return T(1);
    const T g2 = eta * eta + c * c - T(1);
    if (!(g2 > T(0))) return T(1);  // total internal reflection (η < 1 only)
    const T g = sqrt(g2);
    const T a = (g - c) / (g + c);
    const T b = (c * (g + c) - T(1)) / (c * (g - c) + T(1));
    return T(0.5) * a * a * (T(1) + b * b);  // Cook & Torrance 1982; DESIGN.md §5
  }
};

}  // namespace brdfkit
