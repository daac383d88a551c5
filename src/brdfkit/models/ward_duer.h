#pragma once
// Ward-Dür: Ward's lobe with 1/(cosθi cosθo) in place of 1/sqrt(cosθi cosθo), the
// normalization fix compared in seed 002 (Dür 2006; DESIGN.md §6):
// ρ = kd/π + ks exp(−tan²θh/α²) / (4π α² cosθi cosθo). Reciprocal. Sampled as Ward (ward.h).
#include <cmath>
#include <optional>
#include <string_view>

#include "brdfkit/models/ward.h"

namespace brdfkit {

struct WardDuer {
  static std::string_view name() { return "ward-duer"; }
  static std::string_view description() {
    return "Lambert + Ward-Duer, ks exp(-tan^2 th/a^2)/(4 pi a^2 cos_i cos_o)";
  }
  static constexpr bool kReciprocal = true;
  static ParamTable params() {
    return {{"kd", 0.0, 1.0, 0.5, Scope::PerChannel, true, "diffuse albedo (Lambertian kd/pi)"},
            {"ks", 0.0, 1.0, 0.1, Scope::PerChannel, true, "specular scale (Duer 2006)"},
            {"alpha", 1e-3, 1.0, 0.1, Scope::Shared, false, "Ward width, sqrt(2) x RMS slope (Duer 2006)"}};
  }
  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    using std::exp;
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    const T& a = p[2];
    const Vec3<T> h = wi + wo;
    // DESIGN.md §6 (Dür 2006).
    const T spec = p[1] * exp(-ward_detail::exponent<T>(h, a, a)) / (T(4 * kPi) * a * a * wi.z() * wo.z());
    return p[0] * T(kInvPi) + spec;
  }
  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double u_lobe) {
    return ward_detail::sample(p[0], p[1], p[2], p[2], wo, u, u_lobe);
  }
  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    return ward_detail::pdf(p[0], p[1], p[2], p[2], wo, wi);
  }
};

}  // namespace brdfkit
