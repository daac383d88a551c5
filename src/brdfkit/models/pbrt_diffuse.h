#pragma once
// pbrt-v4's `diffuse` material (mmp/pbrt-v4 at commit 5f7a6068: src/pbrt/bxdfs.h DiffuseBxDF::f,
// src/pbrt/materials.h DiffuseMaterial::GetBxDF): ρ = R/π with R = `reflectance` clamped to [0, 1].
#include <optional>
#include <string_view>

#include "brdfkit/core/param.h"
#include "brdfkit/core/vec.h"
#include "brdfkit/core/warp.h"

namespace brdfkit {

struct PbrtDiffuse {
  static std::string_view name() { return "pbrt-diffuse"; }
  static std::string_view description() { return "pbrt-v4 diffuse, reflectance/pi (DiffuseBxDF, bxdfs.h)"; }
  static constexpr bool kReciprocal = true;
  static ParamTable params() {
    return {{"reflectance", 0.0, 1.0, 0.5, Scope::PerChannel, true, "pbrt reflectance R of R/pi"}};
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
