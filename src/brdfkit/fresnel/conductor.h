#pragma once
// Exact unpolarized Fresnel reflectance of a conductor with complex index η + i k seen from a
// medium of index 1 (Born & Wolf, Principles of Optics §14.2; the real-arithmetic form of
// pbrt-v3's FrConductor / Lagarde 2013, "Memo on Fresnel equations"), with c = cos θ, s² = 1 − c²:
//   a² + b² = sqrt((η² − k² − s²)² + 4η²k²),   a = sqrt(½ (a² + b² + η² − k² − s²))
//   Rs = (a² + b² − 2ac + c²) / (a² + b² + 2ac + c²)
//   Rp = Rs (c²(a² + b²) − 2acs² + s⁴) / (c²(a² + b²) + 2acs² + s⁴),   F = (Rs + Rp)/2.
// With k = 0 and η ≥ 1, a = g of the dielectric form and F equals DielectricFresnel (tested).
#include <cmath>

#include "brdfkit/core/param.h"

namespace brdfkit {

template <class T> struct ConductorFresnel {
  T eta;  // real part of the complex index
  T k;    // extinction coefficient

  static ParamTable params() {
    return {{"eta", 0.01, 100.0, 0.2, Scope::PerChannel, false, "real part of the complex index of refraction"},
            {"k", 0.0, 100.0, 3.0, Scope::PerChannel, false, "extinction coefficient (imaginary part of the index)"}};
  }
  explicit ConductorFresnel(const T* p) : eta(p[0]), k(p[1]) {}

  T eval(const T& cos_theta_d) const {
    using std::sqrt;
    const T c = cos_theta_d > T(1) ? T(1) : cos_theta_d;
    if (!(c > T(0))) return T(1);
    const T c2 = c * c;
    const T s2 = T(1) - c2;
    const T t0 = eta * eta - k * k - s2;
    const T a2b2 = sqrt(t0 * t0 + T(4) * eta * eta * k * k);
    const T ha = T(0.5) * (a2b2 + t0);
    // ha ≥ 0 analytically; round-off may dip below, and sqrt's Jet derivative is infinite at 0.
    const T a = ha > T(0) ? sqrt(ha) : T(0);
    const T rs = (a2b2 - T(2) * a * c + c2) / (a2b2 + T(2) * a * c + c2);
    const T t1 = c2 * a2b2 + s2 * s2;
    const T t2 = T(2) * a * c * s2;
    const T rp = rs * (t1 - t2) / (t1 + t2);
    return T(0.5) * (rs + rp);  // Born & Wolf §14.2 (real form as in pbrt-v3 FrConductor)
  }
};

}  // namespace brdfkit
