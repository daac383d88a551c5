#pragma once
// Burley 2012's "principled" BRDF as BRDF Explorer's disney.brdf writes it (wdas/brdf at commit
// f39eb386, src/brdfs/disney.brdf, BRDF()), isotropic:
//   Cdlin = baseColor^2.2 (mon2lin: the .brdf's baseColor is a monitor value)
//   Cspec0 = mix(0.08 specular, Cdlin, metallic)
//   FL, FV, FH = SchlickFresnel(n·l), (n·v), (l·h) = clamp(1 − cos, 0, 1)⁵
//   Fd = mix(1, Fd90, FL) mix(1, Fd90, FV), Fd90 = 0.5 + 2 (l·h)² roughness
//   ss = 1.25 (Fss (1/(n·l + n·v) − 0.5) + 0.5), Fss = mix(1, Fss90, FL) mix(1, Fss90, FV),
//     Fss90 = (l·h)² roughness
//   α = max(0.001, roughness²); Ds = GTR2 (GGX) with α; Fs = mix(Cspec0, 1, FH);
//   Gs = smithG(n·l) smithG(n·v), smithG(c) = 1/(c + sqrt(α²(1 − c²) + c²))  (G1/(2c): it holds
//     the 1/(4 n·l n·v))
//   sheen: FH sheen;  clearcoat: 0.25 clearcoat Gr Fr Dr with Dr = GTR1(n·h; mix(0.1, 0.001,
//     clearcoatGloss)), Fr = mix(0.04, 1, FH), Gr = smithG_{0.25}(n·l) smithG_{0.25}(n·v)
//   ρ = ((1/π) mix(Fd, ss, subsurface) Cdlin + sheen FH)(1 − metallic) + Gs Fs Ds + clearcoat term
// Held at 0 here: anisotropic (isotropic measurements) and specularTint, sheenTint, which tint by
// Cdlin / luminance(Cdlin): that mixes the three channels, and brdfkit's models evaluate a channel
// from that channel's parameters only (models/model.h).
#include <cmath>
#include <string_view>

#include "brdfkit/core/param.h"
#include "brdfkit/core/vec.h"
#include "brdfkit/models/principled_terms.h"

namespace brdfkit {

struct DisneyPrincipled : principled_detail::Sampling<DisneyPrincipled> {
  static std::string_view name() { return "disney-principled"; }
  static std::string_view description() {
    return "Burley 2012 principled BRDF as BRDF Explorer's disney.brdf (tints and anisotropy 0)";
  }
  static constexpr bool kReciprocal = true;
  enum Index { kBaseColor, kMetallic, kSubsurface, kSpecular, kRoughness, kSheen, kClearcoat, kClearcoatGloss };
  static ParamTable params() {
    return {{"baseColor", 0.0, 1.0, 0.5, Scope::PerChannel, false, "disney.brdf baseColor (monitor value, linear = ^2.2)"},
            {"metallic", 0.0, 1.0, 0.0, Scope::Shared, false, "disney.brdf metallic"},
            {"subsurface", 0.0, 1.0, 0.0, Scope::Shared, false, "disney.brdf subsurface"},
            {"specular", 0.0, 1.0, 0.5, Scope::Shared, false, "disney.brdf specular (F0 = 0.08 specular)"},
            {"roughness", 0.01, 1.0, 0.5, Scope::Shared, false, "disney.brdf roughness; alpha = max(0.001, roughness^2)"},
            {"sheen", 0.0, 1.0, 0.0, Scope::Shared, false, "disney.brdf sheen (sheenTint 0)"},
            {"clearcoat", 0.0, 1.0, 0.0, Scope::Shared, false, "disney.brdf clearcoat"},
            {"clearcoatGloss", 0.0, 1.0, 1.0, Scope::Shared, false, "disney.brdf clearcoatGloss"}};
  }

  template <class T> static T smith_g(const T& c, const T& alpha) {
    using std::sqrt;
    const T a = alpha * alpha, b = c * c;
    return T(1) / (c + sqrt(a + b - a * b));
  }
  template <class T> static T alpha(const T* p) { return principled_detail::roughness_alpha(p[kRoughness]); }
  template <class T> static T linear_base(const T* p) {
    using std::pow;
    return pow(p[kBaseColor], 2.2);
  }

  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    using namespace principled_detail;
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    const T nl = wi.z(), nv = wo.z();
    const Vec3<T> h = (wi + wo).normalized();
    const T nh = h.z(), lh = wi.dot(h);
    const T cd = linear_base(p);
    const T cspec0 = lerp(T(0.08) * p[kSpecular], cd, p[kMetallic]);
    const T fl = schlick_weight(nl), fv = schlick_weight(nv), fh = schlick_weight(lh);
    const T fd90 = T(0.5) + T(2) * lh * lh * p[kRoughness];
    const T fd = lerp(T(1), fd90, fl) * lerp(T(1), fd90, fv);
    const T fss90 = lh * lh * p[kRoughness];
    const T fss = lerp(T(1), fss90, fl) * lerp(T(1), fss90, fv);
    const T ss = T(1.25) * (fss * (T(1) / (nl + nv) - T(0.5)) + T(0.5));
    const T a = alpha(p), a2 = a * a;
    const T t = T(1) + (a2 - T(1)) * nh * nh;
    const T ds = a2 / (T(kPi) * t * t);
    const T fs = lerp(cspec0, T(1), fh);
    const T gs = smith_g(nl, a) * smith_g(nv, a);
    const T dr = gtr1(nh, lerp(T(0.1), T(0.001), p[kClearcoatGloss]));
    const T fr = lerp(T(0.04), T(1), fh);
    const T gr = smith_g(nl, T(0.25)) * smith_g(nv, T(0.25));
    return (T(kInvPi) * lerp(fd, ss, p[kSubsurface]) * cd + fh * p[kSheen]) * (T(1) - p[kMetallic]) + gs * fs * ds +
           T(0.25) * p[kClearcoat] * gr * fr * dr;
  }

  static double diffuse_weight(const double* p) {
    return (1 - p[kMetallic]) * (linear_base(p) + p[kSheen]);
  }
  static renderer_sampling::HalfLobe<Ggx<double>> main_lobe(const double* p) {
    return {principled_detail::lerp(0.08 * p[kSpecular], linear_base(p), p[kMetallic]), renderer_sampling::ggx(alpha(p))};
  }
  static renderer_sampling::HalfLobe<Ggx<double>> clearcoat_lobe(const double* p) {
    return principled_detail::clearcoat_lobe(p[kClearcoat], p[kClearcoatGloss]);
  }
};

}  // namespace brdfkit
