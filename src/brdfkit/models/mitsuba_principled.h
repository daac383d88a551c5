#pragma once
// Mitsuba 3's `principled` BSDF, its reflection (front side, spec_trans = 0) as Principled::eval
// computes it (mitsuba-renderer/mitsuba3 v3.9.1, src/bsdfs/principled.cpp, helpers in
// src/bsdfs/principledhelpers.h). Mitsuba's eval returns ρ cosθ of the light direction; ρ is:
//   eta = 2 / (1 − sqrt(0.08 specular)) − 1,  α = max(0.001, roughness²),  cd = wi·h
//   F_d = exact dielectric Fresnel at cd with eta (fresnel())
//   main specular (only where F_d > 0): ((1 − metallic) F_d + metallic Schlick(base_color, cd))
//     · D_GGX(α) · G1(wi) G1(wo) / (4 cosθi cosθo),  G1 = 2 / (1 + sqrt(1 + α² tan²θ))
//   clearcoat: 0.25 clearcoat · Schlick(0.04, cd) · GTR1(h; lerp(0.1, 0.001, clearcoat_gloss))
//     · G1_{0.25}(wi) G1_{0.25}(wo) — Mitsuba adds it as ρ cosθ with no 1/(4 cosθi cosθo)
//     (Disney's BRDF Explorer divides by it: models/disney_principled.h)
//   diffuse: (1 − metallic) base_color/π · lerp(f_diff + f_retro, f_ss, flatness), with
//     Fi, Fo = (1 − cosθ)⁵, f_diff = (1 − Fi/2)(1 − Fo/2), Rr = 2 roughness cd²,
//     f_retro = Rr (Fo + Fi + Fo Fi (Rr − 1)), Fss = lerp(1, Rr/2, Fo) lerp(1, Rr/2, Fi),
//     f_ss = 1.25 (Fss (1/(cosθi + cosθo) − 0.5) + 0.5)   (Burley 2015)
//   sheen: sheen (1 − metallic) (1 − cd)⁵
// Held at 0 here: anisotropic (isotropic measurements), spec_trans (a BRDF), and spec_tint and
// sheen_tint, which tint by base_color / luminance(base_color): that mixes the three channels,
// and brdfkit's models evaluate a channel from that channel's parameters only (models/model.h).
#include <array>
#include <string_view>

#include "brdfkit/core/param.h"
#include "brdfkit/core/vec.h"
#include "brdfkit/fresnel/dielectric.h"
#include "brdfkit/models/principled_terms.h"

namespace brdfkit {

struct MitsubaPrincipled : principled_detail::Sampling<MitsubaPrincipled> {
  static std::string_view name() { return "mitsuba-principled"; }
  static std::string_view description() {
    return "Mitsuba 3 principled BSDF, reflection (v3.9.1 principled.cpp; tints, anisotropy, transmission 0)";
  }
  static constexpr bool kReciprocal = true;
  enum Index { kBaseColor, kRoughness, kMetallic, kSpecular, kSheen, kClearcoat, kClearcoatGloss, kFlatness };
  static ParamTable params() {
    return {{"base_color", 0.0, 1.0, 0.5, Scope::PerChannel, false, "Mitsuba principled base_color (linear RGB)"},
            {"roughness", 0.01, 1.0, 0.5, Scope::Shared, false, "Mitsuba roughness; GGX alpha = max(0.001, roughness^2)"},
            {"metallic", 0.0, 1.0, 0.0, Scope::Shared, false, "Mitsuba metallic"},
            {"specular", 1e-4, 1.0, 0.5, Scope::Shared, false,
             "Mitsuba specular; eta = 2/(1 - sqrt(0.08 specular)) - 1"},
            {"sheen", 0.0, 1.0, 0.0, Scope::Shared, false, "Mitsuba sheen (sheen_tint 0)"},
            {"clearcoat", 0.0, 1.0, 0.0, Scope::Shared, false, "Mitsuba clearcoat"},
            {"clearcoat_gloss", 0.0, 1.0, 0.0, Scope::Shared, false, "Mitsuba clearcoat_gloss"},
            {"flatness", 0.0, 1.0, 0.0, Scope::Shared, false, "Mitsuba flatness (fake subsurface blend)"}};
  }

  template <class T> static T eta(const T* p) {
    using std::sqrt;
    return T(2) / (T(1) - sqrt(T(0.08) * p[kSpecular])) - T(1);
  }
  template <class T> static T alpha(const T* p) { return principled_detail::roughness_alpha(p[kRoughness]); }
  // GGX G1 = 2 / (1 + sqrt(1 + α² tan²θ)), 1 at normal incidence.
  template <class T> static T ggx_g1(const T& a, const Vec3<T>& v) {
    using std::sqrt;
    const T s2 = v.x() * v.x() + v.y() * v.y();
    if (!(s2 > T(0))) return T(1);
    return T(2) / (T(1) + sqrt(T(1) + a * a * s2 / (v.z() * v.z())));
  }

  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    using namespace principled_detail;
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    const Vec3<T> h = (wi + wo).normalized();
    const T cd = wi.dot(h), ci = wi.z(), co = wo.z();
    const T& base = p[kBaseColor];
    const T& metallic = p[kMetallic];
    const T w_d = schlick_weight(cd);
    T value(0);
    const T f_d = DielectricFresnel<T>(std::array<T, 1>{eta(p)}.data()).eval(cd);
    if (f_d > T(0)) {
      const T a = alpha(p);
      const T t = h.z() * h.z() * (a * a - T(1)) + T(1);
      T d = a * a / (T(kPi) * t * t);
      if (!(d * h.z() > T(1e-20))) d = T(0);
      const T f = (T(1) - metallic) * f_d + metallic * (base + (T(1) - base) * w_d);
      value += f * d * ggx_g1(a, wi) * ggx_g1(a, wo) / (T(4) * ci * co);
    }
    if (p[kClearcoat] > T(0)) {
      const T f_cc = T(0.04) + T(0.96) * w_d;
      const T d_cc = gtr1(h.z(), lerp(T(0.1), T(0.001), p[kClearcoatGloss]));
      value += T(0.25) * p[kClearcoat] * f_cc * d_cc * ggx_g1(T(0.25), wi) * ggx_g1(T(0.25), wo);
    }
    const T fo = schlick_weight(co), fi = schlick_weight(ci);
    const T f_diff = (T(1) - T(0.5) * fi) * (T(1) - T(0.5) * fo);
    const T rr = T(2) * p[kRoughness] * cd * cd;
    const T f_retro = rr * (fo + fi + fo * fi * (rr - T(1)));
    const T fss = lerp(T(1), rr / T(2), fo) * lerp(T(1), rr / T(2), fi);
    const T f_ss = T(1.25) * (fss * (T(1) / (co + ci) - T(0.5)) + T(0.5));
    value += (T(1) - metallic) * base * T(kInvPi) * lerp(f_diff + f_retro, f_ss, p[kFlatness]);
    value += p[kSheen] * (T(1) - metallic) * w_d;
    return value;
  }

  static double diffuse_weight(const double* p) {
    return (1 - p[kMetallic]) * p[kBaseColor] + p[kSheen] * (1 - p[kMetallic]);
  }
  static renderer_sampling::HalfLobe<Ggx<double>> main_lobe(const double* p) {
    const double f0 = DielectricFresnel<double>(std::array<double, 1>{eta(p)}.data()).eval(1.0);
    return {(1 - p[kMetallic]) * f0 + p[kMetallic] * p[kBaseColor], renderer_sampling::ggx(alpha(p))};
  }
  static renderer_sampling::HalfLobe<Ggx<double>> clearcoat_lobe(const double* p) {
    return principled_detail::clearcoat_lobe(p[kClearcoat], p[kClearcoatGloss]);
  }
};

}  // namespace brdfkit
