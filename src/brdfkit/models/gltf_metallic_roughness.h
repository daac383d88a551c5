#pragma once
// The glTF 2.0 metallic-roughness material, evaluated as the specification's Appendix B
// ("BRDF Implementation", glTF 2.0 specification, KhronosGroup/glTF specification/2.0/
// Specification.adoc) with the extensions KHR_materials_ior (ior replaces 1.5) and
// KHR_materials_specular (extensions/2.0/Khronos/KHR_materials_specular/README.md,
// "Implementation"):
//   α = roughness²
//   D = α² / (π ((n·h)² (α² − 1) + 1)²)
//   V = 1 / (2 (|n·v| sqrt(α² + (1 − α²)(n·l)²) + |n·l| sqrt(α² + (1 − α²)(n·v)²)))   height-correlated
//   specular_brdf = V D,  w = (1 − |v·h|)⁵
//   f0 = min(((ior − 1)/(ior + 1))² specularColor, 1) specular,  f90 = specular
//   F = mix(f0, f90, w)
//   dielectric = F specular_brdf + (1 − max_value(F)) baseColor/π
//   metal = (baseColor + (1 − baseColor) w) specular_brdf
//   ρ = mix(dielectric, metal, metallic)
// specularColorFactor is one grey value here: with a coloured one, max_value(F) mixes the three
// channels, and brdfkit's models evaluate a channel from that channel's parameters only
// (models/model.h); a grey factor makes max_value(F) = F exactly. Textures, normal maps, occlusion
// and emission are outside a BRDF fit.
#include <optional>
#include <string_view>

#include "brdfkit/core/param.h"
#include "brdfkit/core/vec.h"
#include "brdfkit/models/renderer_sampling.h"

namespace brdfkit {

struct GltfMetallicRoughness {
  static std::string_view name() { return "gltf-metallic-roughness"; }
  static std::string_view description() {
    return "glTF 2.0 metallic-roughness (spec Appendix B) with KHR_materials_ior and KHR_materials_specular";
  }
  static constexpr bool kReciprocal = true;
  enum Index { kBaseColor, kMetallic, kRoughness, kIor, kSpecular, kSpecularColor };
  static ParamTable params() {
    return {{"base_color", 0.0, 1.0, 0.5, Scope::PerChannel, false, "pbrMetallicRoughness.baseColorFactor (linear RGB)"},
            {"metallic", 0.0, 1.0, 0.0, Scope::Shared, false, "pbrMetallicRoughness.metallicFactor"},
            {"roughness", 0.01, 1.0, 0.5, Scope::Shared, false,
             "pbrMetallicRoughness.roughnessFactor; GGX alpha = roughness^2 (spec Appendix B)"},
            {"ior", 1.0, 5.0, 1.5, Scope::Shared, false, "KHR_materials_ior.ior (1.5 without the extension)"},
            {"specular", 0.0, 1.0, 1.0, Scope::Shared, false, "KHR_materials_specular.specularFactor"},
            {"specular_color", 0.0, 10.0, 1.0, Scope::Shared, false,
             "KHR_materials_specular.specularColorFactor, grey (all three components)"}};
  }

  // The dielectric Fresnel F = mix(f0, f90, w) of KHR_materials_specular.
  template <class T> static T dielectric_fresnel(const T* p, const T& w) {
    const T r = (p[kIor] - T(1)) / (p[kIor] + T(1));
    T f0 = r * r * p[kSpecularColor];
    if (f0 > T(1)) f0 = T(1);
    f0 = f0 * p[kSpecular];
    return f0 + (p[kSpecular] - f0) * w;
  }

  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    using std::sqrt;
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    const Vec3<T> s = wi + wo;
    const T len = sqrt(s.squaredNorm());
    const T nh = s.z() / len, vh = T(0.5) * len;  // |wi + wo| = 2 v·h for unit directions
    const T nl = wi.z(), nv = wo.z();
    const T a = p[kRoughness] * p[kRoughness], a2 = a * a;
    const T t = nh * nh * (a2 - T(1)) + T(1);
    const T d = a2 / (T(kPi) * t * t);
    const T vis = T(0.5) / (nv * sqrt(a2 + (T(1) - a2) * nl * nl) + nl * sqrt(a2 + (T(1) - a2) * nv * nv));
    const T spec = vis * d;
    const T m = T(1) - vh, m2 = m * m, w = m2 * m2 * m;
    const T f = dielectric_fresnel(p, w);
    const T& base = p[kBaseColor];
    const T dielectric = f * spec + (T(1) - f) * base * T(kInvPi);
    const T metal = (base + (T(1) - base) * w) * spec;
    return (T(1) - p[kMetallic]) * dielectric + p[kMetallic] * metal;
  }

  // Diffuse weight (1 − metallic)(1 − F) baseColor at normal incidence; specular weight F or the
  // metal's baseColor.
  static renderer_sampling::HalfLobe<Ggx<double>> lobe(const double* p) {
    const double f = dielectric_fresnel(p, 0.0);
    return {(1 - p[kMetallic]) * f + p[kMetallic] * p[kBaseColor],
            renderer_sampling::ggx(p[kRoughness] * p[kRoughness])};
  }
  static double diffuse_weight(const double* p) {
    return (1 - p[kMetallic]) * (1 - dielectric_fresnel(p, 0.0)) * p[kBaseColor];
  }
  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double u_lobe) {
    const auto none = renderer_sampling::HalfLobe<Ggx<double>>{0.0, renderer_sampling::ggx(0.5)};
    return renderer_sampling::sample(diffuse_weight(p), lobe(p), none, wo, u, u_lobe);
  }
  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    const auto none = renderer_sampling::HalfLobe<Ggx<double>>{0.0, renderer_sampling::ggx(0.5)};
    return renderer_sampling::pdf(diffuse_weight(p), lobe(p), none, wo, wi);
  }
};

}  // namespace brdfkit
