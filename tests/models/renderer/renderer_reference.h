#pragma once
// Independent transcriptions of the renderers' published formulas, written from the renderers'
// sources in their own form (vectors, complex arithmetic, the anisotropic expressions with
// αu = αv), not from brdfkit's models: the reference the catalogue's renderer models are compared
// with (test_renderer_reference.cpp). Each takes the light direction L and the view direction V
// in the local frame (n = +z) and returns ρ for one channel.
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>

#include "brdfkit/core/vec.h"

namespace brdfkit::test::reference {

using V3 = Vec3d;
inline double sqr(double x) { return x * x; }
inline double mix(double a, double b, double t) { return a * (1 - t) + b * t; }
inline double heaviside(double x) { return x > 0 ? 1.0 : 0.0; }

// Unpolarized Fresnel reflectance of a complex index η + ik from air, by Snell's law in complex
// arithmetic (pbrt-v4 src/pbrt/util/scattering.h FrComplex).
inline double fr_complex(double cos_i, double eta, double k) {
  using C = std::complex<double>;
  cos_i = std::clamp(cos_i, 0.0, 1.0);
  const C e(eta, k);
  const double sin2_i = 1 - cos_i * cos_i;
  const C sin2_t = sin2_i / (e * e);
  const C cos_t = std::sqrt(1.0 - sin2_t);
  const C r_parl = (e * cos_i - cos_t) / (e * cos_i + cos_t);
  const C r_perp = (cos_i - e * cos_t) / (cos_i + e * cos_t);
  return (std::norm(r_parl) + std::norm(r_perp)) / 2;
}

// glTF 2.0 Appendix B with KHR_materials_ior and KHR_materials_specular ("Implementation"),
// for RGB base colour (the max_value of the Fresnel colour needs all three channels).
struct Gltf {
  std::array<double, 3> base;
  double metallic, roughness, ior = 1.5, specular = 1, specular_color = 1;
  double alpha_of_roughness(double r) const { return r * r; }
  std::array<double, 3> eval(const V3& L, const V3& V, double alpha) const {
    const V3 N(0, 0, 1), H = (L + V).normalized();
    const double NdotL = N.dot(L), NdotV = N.dot(V), NdotH = N.dot(H), VdotH = V.dot(H), LdotH = L.dot(H);
    const double a2 = alpha * alpha;
    const double D = a2 * heaviside(NdotH) / (kPi * sqr(NdotH * NdotH * (a2 - 1) + 1));
    const double G = 2 * std::abs(NdotL) * std::abs(NdotV) * heaviside(LdotH) * heaviside(VdotH) /
                     (std::abs(NdotV) * std::sqrt(a2 + (1 - a2) * NdotL * NdotL) +
                      std::abs(NdotL) * std::sqrt(a2 + (1 - a2) * NdotV * NdotV));
    const double specular_brdf = G * D / (4 * std::abs(NdotV) * std::abs(NdotL));
    const double fresnel_w = std::pow(1 - std::abs(VdotH), 5);
    std::array<double, 3> fr{}, out{};
    for (int c = 0; c < 3; ++c) {
      const double f0 = std::min(sqr((ior - 1) / (ior + 1)) * specular_color, 1.0) * specular;
      fr[c] = mix(f0, specular, fresnel_w);
    }
    const double fr_max = std::max({fr[0], fr[1], fr[2]});
    for (int c = 0; c < 3; ++c) {
      const double dielectric = fr[c] * specular_brdf + (1 - fr_max) * base[c] / kPi;
      const double metal = (base[c] + (1 - base[c]) * fresnel_w) * specular_brdf;
      out[c] = mix(dielectric, metal, metallic);
    }
    return out;
  }
};

// Mitsuba 3 v3.9.1 MicrofacetDistribution (include/mitsuba/render/microfacet.h), αu = αv = α.
struct MitsubaMicrofacet {
  bool beckmann;
  double au, av;
  double eval(const V3& m) const {
    const double c2 = m.z() * m.z();
    double r;
    if (beckmann) r = std::exp(-(sqr(m.x() / au) + sqr(m.y() / av)) / c2) / (kPi * au * av * sqr(c2));
    else r = 1 / (kPi * au * av * sqr(sqr(m.x() / au) + sqr(m.y() / av) + sqr(m.z())));
    return r * m.z() > 1e-20 ? r : 0.0;
  }
  double smith_g1(const V3& v, const V3& m) const {
    const double xy_alpha_2 = sqr(au * v.x()) + sqr(av * v.y());
    const double tan_theta_alpha_2 = xy_alpha_2 / sqr(v.z());
    double result;
    if (beckmann) {
      const double a = 1 / std::sqrt(tan_theta_alpha_2), a_sqr = a * a;
      result = a >= 1.6 ? 1.0 : (3.535 * a + 2.181 * a_sqr) / (1 + 2.276 * a + 2.577 * a_sqr);
    } else {
      result = 2 / (1 + std::sqrt(1 + tan_theta_alpha_2));
    }
    if (xy_alpha_2 == 0) result = 1;
    if (v.dot(m) * v.z() <= 0) result = 0;
    return result;
  }
};

// Mitsuba 3 fresnel() (include/mitsuba/render/fresnel.h), the dielectric case, cos_theta_i > 0.
inline double mitsuba_fresnel_dielectric(double cos_theta_i, double eta) {
  const double eta_ti = 1 / eta;
  const double cos_theta_t = std::sqrt(std::max(0.0, 1 - (1 - cos_theta_i * cos_theta_i) * eta_ti * eta_ti));
  if (eta == 1 || cos_theta_i == 0) return eta == 1 ? 0.0 : 1.0;
  const double a_s = (cos_theta_i - eta * cos_theta_t) / (cos_theta_i + eta * cos_theta_t);
  const double a_p = (cos_theta_t - eta * cos_theta_i) / (cos_theta_t + eta * cos_theta_i);
  return 0.5 * (a_s * a_s + a_p * a_p);
}

// roughconductor::eval (src/bsdfs/roughconductor.cpp): D G F sr / (4 cosθ_wi), divided by the
// other cosine to give ρ. Mitsuba's si.wi is the camera side, its wo the light side.
inline double mitsuba_roughconductor(bool beckmann, double alpha, double eta, double k, double sr, const V3& L,
                                     const V3& V) {
  const V3 wi = V, wo = L;
  if (!(wi.z() > 0 && wo.z() > 0)) return 0;
  const V3 H = (wo + wi).normalized();
  const MitsubaMicrofacet distr{beckmann, std::max(alpha, 1e-4), std::max(alpha, 1e-4)};
  const double D = distr.eval(H);
  const double G = distr.smith_g1(wi, H) * distr.smith_g1(wo, H);
  const double result = D * G / (4 * wi.z());
  return fr_complex(wi.dot(H), eta, k) * result * sr / wo.z();
}

// Principled::eval (src/bsdfs/principled.cpp) front-side reflection, spec_trans = anisotropic =
// spec_tint = sheen_tint = 0.
struct MitsubaPrincipled {
  double base, roughness, metallic, specular, sheen = 0, clearcoat = 0, clearcoat_gloss = 0, flatness = 0;
  double alpha() const { return std::max(0.001, sqr(roughness)); }
  static double schlick_weight(double c) {
    const double m = std::clamp(1 - c, 0.0, 1.0);
    return sqr(sqr(m)) * m;
  }
  static double smith_ggx1(const V3& v, const V3& wh, double alpha) {
    const double cos2 = sqr(std::abs(v.z())), tan2 = (1 - cos2) / cos2;
    double r = 2 / (1 + std::sqrt(1 + alpha * alpha * tan2));
    if (v.z() == 1) r = 1;
    if (v.dot(wh) * v.z() <= 0) r = 0;
    return r;
  }
  double eval(const V3& L, const V3& V, double a) const {
    const V3 wi = V, wo = L;
    const double cos_theta_i = wi.z(), cos_theta_o = wo.z();
    if (!(cos_theta_i > 0 && cos_theta_o > 0)) return 0;
    const double brdf = 1 - metallic;
    const double eta = 2 / (1 - std::sqrt(0.08 * specular)) - 1;
    const V3 wh = (wi + wo).normalized();
    const double F_diel = mitsuba_fresnel_dielectric(wi.dot(wh), eta);
    const MitsubaMicrofacet spec{false, a, a};
    const double D = spec.eval(wh), G = spec.smith_g1(wi, wh) * spec.smith_g1(wo, wh);
    double value = 0;
    if (F_diel > 0) {
      const double F_schlick = metallic * mix(schlick_weight(std::abs(wi.dot(wh))), 1.0, base);
      const double F = (1 - metallic) * F_diel + F_schlick;
      value += F * D * G / (4 * std::abs(cos_theta_i));
    }
    if (clearcoat > 0) {
      const double Fcc = mix(schlick_weight(std::abs(wi.dot(wh))), 1.0, 0.04);
      const double ac = mix(0.1, 0.001, clearcoat_gloss), a2 = ac * ac;
      double Dcc = (a2 - 1) / (kPi * std::log(a2) * (1 + (a2 - 1) * sqr(wh.z())));
      if (!(Dcc * wh.z() > 1e-20)) Dcc = 0;
      const double Gcc = smith_ggx1(wi, wh, 0.25) * smith_ggx1(wo, wh, 0.25);
      value += clearcoat * 0.25 * Fcc * Dcc * Gcc * std::abs(cos_theta_o);
    }
    const double Fo = schlick_weight(std::abs(cos_theta_o)), Fi = schlick_weight(std::abs(cos_theta_i));
    const double f_diff = (1 - 0.5 * Fi) * (1 - 0.5 * Fo);
    const double cos_theta_d = wh.dot(wo);
    const double Rr = 2 * roughness * sqr(cos_theta_d);
    const double f_retro = Rr * (Fo + Fi + Fo * Fi * (Rr - 1));
    const double Fss90 = Rr / 2;
    const double Fss = mix(1.0, Fss90, Fo) * mix(1.0, Fss90, Fi);
    const double f_ss = 1.25 * (Fss * (1 / (std::abs(cos_theta_o) + std::abs(cos_theta_i)) - 0.5) + 0.5);
    value += brdf * std::abs(cos_theta_o) * base / kPi * mix(f_diff + f_retro, f_ss, flatness);
    value += sheen * (1 - metallic) * schlick_weight(std::abs(cos_theta_d)) * std::abs(cos_theta_o);
    return value / cos_theta_o;
  }
};

// pbrt-v4 ConductorBxDF::f (src/pbrt/bxdfs.h) with TrowbridgeReitzDistribution
// (src/pbrt/util/scattering.h), isotropic; wo the camera side.
inline double pbrt_conductor(double alpha, double eta, double k, const V3& L, const V3& V) {
  const V3 wo = V, wi = L;
  if (!(wo.z() * wi.z() > 0)) return 0;
  alpha = std::max(alpha, 1e-4);
  auto tan2 = [](const V3& w) { return (1 - w.z() * w.z()) / (w.z() * w.z()); };
  auto lambda = [&](const V3& w) { return (std::sqrt(1 + alpha * alpha * tan2(w)) - 1) / 2; };
  const V3 wm = (wi + wo).normalized();
  const double cos4 = sqr(wm.z() * wm.z());
  const double phi = std::atan2(wm.y(), wm.x());
  const double e = tan2(wm) * (sqr(std::cos(phi) / alpha) + sqr(std::sin(phi) / alpha));
  const double D = cos4 < 1e-16 ? 0.0 : 1 / (kPi * alpha * alpha * cos4 * sqr(1 + e));
  const double G = 1 / (1 + lambda(wo) + lambda(wi));
  const double F = fr_complex(std::abs(wo.dot(wm)), eta, k);
  return D * F * G / (4 * std::abs(wi.z()) * std::abs(wo.z()));
}
// ConductorMaterial::GetBxDF's reflectance parameterization.
inline double pbrt_k_from_reflectance(double r) {
  r = std::clamp(r, 0.0, 0.9999);
  return 2 * std::sqrt(r) / std::sqrt(std::max(0.0, 1 - r));
}

// BRDF Explorer disney.brdf BRDF(L, V, N, X, Y), transcribed from its GLSL (specularTint,
// sheenTint and anisotropic given, evaluated as written).
struct Disney {
  std::array<double, 3> baseColor;
  double metallic = 0, subsurface = 0, specular = 0.5, roughness = 0.5, specularTint = 0, anisotropic = 0,
         sheen = 0, sheenTint = 0, clearcoat = 0, clearcoatGloss = 1;
  bool gamma = true;  // mon2lin; false: the mistake of taking baseColor as linear
  static double SchlickFresnel(double u) {
    const double m = std::clamp(1 - u, 0.0, 1.0), m2 = m * m;
    return m2 * m2 * m;
  }
  static double GTR1(double NdotH, double a) {
    if (a >= 1) return 1 / kPi;
    const double a2 = a * a, t = 1 + (a2 - 1) * NdotH * NdotH;
    return (a2 - 1) / (kPi * std::log(a2) * t);
  }
  static double GTR2_aniso(double NdotH, double HdotX, double HdotY, double ax, double ay) {
    return 1 / (kPi * ax * ay * sqr(sqr(HdotX / ax) + sqr(HdotY / ay) + NdotH * NdotH));
  }
  static double smithG_GGX(double NdotV, double alphaG) {
    const double a = alphaG * alphaG, b = NdotV * NdotV;
    return 1 / (NdotV + std::sqrt(a + b - a * b));
  }
  static double smithG_GGX_aniso(double NdotV, double VdotX, double VdotY, double ax, double ay) {
    return 1 / (NdotV + std::sqrt(sqr(VdotX * ax) + sqr(VdotY * ay) + sqr(NdotV)));
  }
  std::array<double, 3> BRDF(const V3& L, const V3& V, double rough_for_alpha) const {
    const V3 N(0, 0, 1), X(1, 0, 0), Y(0, 1, 0);
    const double NdotL = N.dot(L), NdotV = N.dot(V);
    if (NdotL < 0 || NdotV < 0) return {0, 0, 0};
    const V3 H = (L + V).normalized();
    const double NdotH = N.dot(H), LdotH = L.dot(H);
    std::array<double, 3> Cdlin, out;
    for (int c = 0; c < 3; ++c) Cdlin[c] = gamma ? std::pow(baseColor[c], 2.2) : baseColor[c];
    const double Cdlum = .3 * Cdlin[0] + .6 * Cdlin[1] + .1 * Cdlin[2];
    const double FL = SchlickFresnel(NdotL), FV = SchlickFresnel(NdotV);
    const double Fd90 = 0.5 + 2 * LdotH * LdotH * roughness;
    const double Fd = mix(1.0, Fd90, FL) * mix(1.0, Fd90, FV);
    const double Fss90 = LdotH * LdotH * roughness;
    const double Fss = mix(1.0, Fss90, FL) * mix(1.0, Fss90, FV);
    const double ss = 1.25 * (Fss * (1 / (NdotL + NdotV) - .5) + .5);
    const double aspect = std::sqrt(1 - anisotropic * .9);
    const double ax = std::max(.001, sqr(rough_for_alpha) / aspect), ay = std::max(.001, sqr(rough_for_alpha) * aspect);
    const double Ds = GTR2_aniso(NdotH, H.dot(X), H.dot(Y), ax, ay);
    const double FH = SchlickFresnel(LdotH);
    const double Gs = smithG_GGX_aniso(NdotL, L.dot(X), L.dot(Y), ax, ay) * smithG_GGX_aniso(NdotV, V.dot(X), V.dot(Y), ax, ay);
    const double Dr = GTR1(NdotH, mix(.1, .001, clearcoatGloss));
    const double Fr = mix(.04, 1.0, FH);
    const double Gr = smithG_GGX(NdotL, .25) * smithG_GGX(NdotV, .25);
    for (int c = 0; c < 3; ++c) {
      const double Ctint = Cdlum > 0 ? Cdlin[c] / Cdlum : 1;
      const double Cspec0 = mix(specular * .08 * mix(1.0, Ctint, specularTint), Cdlin[c], metallic);
      const double Csheen = mix(1.0, Ctint, sheenTint);
      const double Fs = mix(Cspec0, 1.0, FH);
      const double Fsheen = FH * sheen * Csheen;
      out[c] = ((1 / kPi) * mix(Fd, ss, subsurface) * Cdlin[c] + Fsheen) * (1 - metallic) + Gs * Fs * Ds +
               .25 * clearcoat * Gr * Fr * Dr;
    }
    return out;
  }
};

}  // namespace brdfkit::test::reference
