#pragma once
// Anisotropic GGX (Trowbridge-Reitz): D(m) = 1 / (π αx αy (mx²/αx² + my²/αy² + mz²)²)
// (pbrt-v4 src/pbrt/util/scattering.h TrowbridgeReitzDistribution::D,
// written in m's components). αx = αy = α is ndf/ggx.h. Interface: ndf/anisotropic_distribution.h.
#include <cmath>
#include <string_view>
#include <type_traits>

#include "brdfkit/core/param.h"
#include "brdfkit/core/vec.h"
#include "brdfkit/ndf/anisotropic_distribution.h"

namespace brdfkit {

template <class T>
struct GgxAnisotropic {
  static constexpr std::string_view kName = "ggx", kTitle = "GGX";
  T ax, ay;

  static ParamTable params() {
    return {
        {"alpha_x", 1e-3, 2.0, 0.2, Scope::Shared, false, "GGX width along the lobe's tangent (pbrt-v4 scattering.h)"},
        {"alpha_y", 1e-3, 2.0, 0.2, Scope::Shared, false,
         "GGX width along the lobe's bitangent (pbrt-v4 scattering.h)"}};
  }
  explicit GgxAnisotropic(const T* p) : ax(p[0]), ay(p[1]) {}

  T D(const Vec3<T>& m) const {
    if (!(m.z() > T(0))) return T(0);
    const T x = m.x() / ax, y = m.y() / ay;
    const T s = x * x + y * y + m.z() * m.z();
    return T(1) / (T(kPi) * ax * ay * s * s);
  }
  // Λ = (sqrt(1 + α(φ)² tan²θ) − 1)/2 (pbrt-v4 scattering.h TrowbridgeReitzDistribution::Lambda),
  // as y/(2 (sqrt(1 + y) + 1)) without cancellation for small y.
  T Lambda(const Vec3<T>& w) const {
    using std::sqrt;
    const T y = stretched_tan2(w, ax, ay);
    return y / (T(2) * (sqrt(T(1) + y) + T(1)));
  }

  // The unit-width slope radius from its CDF r²/(1 + r²) (Walter et al. 2007 Eq. 35 at α = 1),
  // stretched by (αx, αy) (Heitz 2014, stretch invariance).
  Vec3d sample(const Vec2d& u) const requires std::is_same_v<T, double> {
    const double r = std::sqrt(u.x() / (1.0 - u.x()));
    const double phi = 2 * kPi * u.y();
    return normal_of_slope(ax * r * std::cos(phi), ay * r * std::sin(phi));
  }
  double pdf(const Vec3d& m) const requires std::is_same_v<T, double> { return D(m) * std::max(0.0, m.z()); }
};

}  // namespace brdfkit
