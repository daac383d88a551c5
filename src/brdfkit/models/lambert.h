#pragma once
// Lambertian diffuse reflection ρ = kd/π (DESIGN.md §6), sampled cosine-weighted.
#include <optional>
#include <string_view>

#include "brdfkit/core/warp.h"
#include "brdfkit/core/param.h"

namespace brdfkit {

struct Lambert {
  static std::string_view name() { return "lambert"; }
  static std::string_view description() { return "Lambertian diffuse, kd/pi"; }
  static constexpr bool kReciprocal = true;
  static ParamTable params() {
    return {{"kd", 0.0, 1.0, 0.5, Scope::PerChannel, true, "diffuse albedo (directional-hemispherical reflectance)"}};
  }
  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    return p[0] * T(kInvPi);
  }
  static std::optional<Vec3d> sample(const double*, int, const Vec3d&, const Vec2d& u, double) {
    return square_to_cosine_hemisphere(u);
  }
  static double pdf(const double*, int, const Vec3d&, const Vec3d& wi) { return cosine_hemisphere_pdf(wi); }
};

}  // namespace brdfkit
