#pragma once
// pbrt-v4's `mix` of a diffuse and a conductor material (mmp/pbrt-v4 at commit 5f7a6068:
// src/pbrt/materials.h MixMaterial::ChooseMaterial: material 1 where amount ≥ u, u a hash of the
// shading point and wo, so a pixel's expected value is (1 − amount) ρ0 + amount ρ1): pbrt-v4's one
// way to put a diffuse and a glossy term on one surface in closed form (its `coateddiffuse` layer
// is evaluated stochastically: no closed form, not in the catalogue).
#include <optional>
#include <string_view>

#include "brdfkit/core/param.h"
#include "brdfkit/core/vec.h"
#include "brdfkit/core/warp.h"
#include "brdfkit/models/lobe_mixture.h"
#include "brdfkit/models/pbrt_conductor.h"

namespace brdfkit {

// MakeNamedMaterial "diffuse" + "conductor" (reflectance form) + "mix" with `amount`.
struct PbrtMixDiffuseConductor {
  static std::string_view name() { return "pbrt-mix-diffuse-conductor"; }
  static std::string_view description() {
    return "pbrt-v4 mix of diffuse and conductor(reflectance): (1-amount) R/pi + amount conductor";
  }
  static constexpr bool kReciprocal = true;
  enum Index { kReflectance, kAmount, kConductorReflectance, kRoughness };
  static ParamTable params() {
    return {{"reflectance", 0.0, 1.0, 0.5, Scope::PerChannel, false, "pbrt diffuse reflectance R (material 0)"},
            {"amount", 0.0, 1.0, 0.5, Scope::Shared, false, "pbrt mix amount: the weight of the conductor (material 1)"},
            {"conductor_reflectance", 1e-6, 0.9999, 0.5, Scope::PerChannel, false,
             "pbrt conductor reflectance r (eta 1, k = 2 sqrt(r)/sqrt(1-r))"},
            {"roughness", 2e-6, 1.0, 0.01, Scope::Shared, false, pbrt_detail::kRoughnessDoc}};
  }
  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    const T conductor =
        pbrt_detail::conductor_f(p[kRoughness], T(1), pbrt_detail::k_from_reflectance(p[kConductorReflectance]), wi, wo);
    return (T(1) - p[kAmount]) * p[kReflectance] * T(kInvPi) + p[kAmount] * conductor;
  }
  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double u_lobe) {
    const auto prob = lobes::selection_probabilities<2>(
        {(1 - p[kAmount]) * p[kReflectance], p[kAmount] * p[kConductorReflectance]});
    if (lobes::pick(prob, u_lobe) == 0) return square_to_cosine_hemisphere(u);
    return pbrt_detail::sample_ggx(p[kRoughness], wo, u);
  }
  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    if (!(wo.z() > 0 && wi.z() > 0)) return 0.0;
    const auto prob = lobes::selection_probabilities<2>(
        {(1 - p[kAmount]) * p[kReflectance], p[kAmount] * p[kConductorReflectance]});
    return prob[0] * cosine_hemisphere_pdf(wi) + prob[1] * pbrt_detail::pdf_ggx(p[kRoughness], wo, wi);
  }
};

}  // namespace brdfkit
