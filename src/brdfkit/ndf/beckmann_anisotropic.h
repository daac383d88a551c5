#pragma once
// Anisotropic Beckmann: D(m) = exp(−(mx²/αx² + my²/αy²)/mz²) / (π αx αy mz⁴) (pbrt-v3
// src/core/microfacet.cpp BeckmannDistribution::D, written in m's components). αx = αy = α
// is ndf/beckmann.h. Interface: ndf/anisotropic_distribution.h.
#include <cmath>
#include <string_view>
#include <type_traits>

#include "brdfkit/core/param.h"
#include "brdfkit/core/vec.h"
#include "brdfkit/ndf/anisotropic_distribution.h"

namespace brdfkit {

template <class T>
struct BeckmannAnisotropic {
  static constexpr std::string_view kName = "beckmann", kTitle = "Beckmann";
  T ax, ay;

  static ParamTable params() {
    return {{"alpha_x", 1e-3, 2.0, 0.2, Scope::Shared, false,
             "Beckmann width along the lobe's tangent, sqrt(2) x RMS slope (pbrt-v3 microfacet.cpp)"},
            {"alpha_y", 1e-3, 2.0, 0.2, Scope::Shared, false,
             "Beckmann width along the lobe's bitangent, sqrt(2) x RMS slope (pbrt-v3 microfacet.cpp)"}};
  }
  explicit BeckmannAnisotropic(const T* p) : ax(p[0]), ay(p[1]) {}

  T D(const Vec3<T>& m) const {
    using std::exp;
    if (!(m.z() > T(0))) return T(0);
    const T x = m.x() / ax, y = m.y() / ay, z2 = m.z() * m.z();
    return exp(-(x * x + y * y) / z2) / (T(kPi) * ax * ay * z2 * z2);
  }
  // Λ = (erf(a) − 1)/2 + exp(−a²)/(2a√π), a = 1/(α(φ) tanθ) (pbrt-v3 microfacet.cpp
  // BeckmannDistribution::Lambda), through erfc.
  T Lambda(const Vec3<T>& w) const {
    using std::erfc;
    using std::exp;
    using std::sqrt;
    const T t2 = stretched_tan2(w, ax, ay);
    if (!(t2 > T(0))) return T(0);
    const T a = T(1) / sqrt(t2);
    return -erfc(a) / T(2) + exp(-a * a) / (T(2) * a * T(std::sqrt(kPi)));
  }

  // The unit-width slope radius from its CDF 1 − exp(−r²) (Walter et al. 2007 Eq. 28 at α = 1),
  // stretched by (αx, αy) (Heitz 2014, stretch invariance).
  Vec3d sample(const Vec2d& u) const requires std::is_same_v<T, double> {
    const double r = std::sqrt(-std::log1p(-u.x()));
    const double phi = 2 * kPi * u.y();
    return normal_of_slope(ax * r * std::cos(phi), ay * r * std::sin(phi));
  }
  double pdf(const Vec3d& m) const requires std::is_same_v<T, double> { return D(m) * std::max(0.0, m.z()); }
};

}  // namespace brdfkit
