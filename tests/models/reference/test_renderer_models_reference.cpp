// The renderers' own BSDFs in the catalogue against transcriptions of the renderers' sources,
// written here in the renderers' own variables and argument roles:
//   gltf-metallic-roughness   glTF 2.0 Specification.adoc, Appendix B (height-correlated Smith
//                             visibility, fresnel_mix), with KHR_materials_specular's fresnel_mix
//                             (extensions/2.0/Khronos/KHR_materials_specular/README.md, "Implementation")
//   mitsuba-roughconductor-*  Mitsuba 3 src/bsdfs/roughconductor.cpp eval(), include/mitsuba/render/
//                             microfacet.h (eval, smith_g1), fresnel_conductor
//   mitsuba-principled        Mitsuba 3 src/bsdfs/principled.cpp eval(), principledhelpers.h
//   pbrt-*                    pbrt-v4 src/pbrt/bxdfs.h ConductorBxDF::f, DiffuseBxDF::f,
//                             util/scattering.h TrowbridgeReitzDistribution, FrComplex,
//                             materials.h ConductorMaterial (reflectance → eta = 1, k = 2√r/√(1 − r)),
//                             MixMaterial (its expected value (1 − amount) f0 + amount f1)
//   disney-principled         wdas/brdf src/brdfs/disney.brdf BRDF()
// Mitsuba's eval takes si.wi towards the camera and wo towards the light and returns ρ · cosθ of
// the light direction; pbrt's f takes wo towards the camera and wi towards the light; glTF and
// the .brdf take L (light) and V (view). Here the light direction is brdfkit's wi and the view
// direction its wo (DESIGN.md §2). Every term is closed-form: bound 1e-10 relative.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "brdfkit/models/model.h"
#include "reference_fresnel.h"
#include "reference_pairs.h"

namespace brdfkit::test::ref {
namespace {

double schlick_weight(double c) { return std::pow(std::clamp(1 - c, 0.0, 1.0), 5); }

// ---- glTF 2.0 -------------------------------------------------------------------------------
double gltf_brdf(const Vec3d& L, const Vec3d& V, double base, double metallic, double roughness, double ior,
                 double specular, double specular_color, double norm = kPi) {
  const Vec3d N(0, 0, 1), H = (L + V).normalized();
  const double NdotL = N.dot(L), NdotV = N.dot(V), NdotH = N.dot(H), VdotH = V.dot(H);
  const double alpha = roughness * roughness, a2 = alpha * alpha;
  const double D = a2 / (norm * sqr(NdotH * NdotH * (a2 - 1) + 1));
  const double Vis = 1 / (2 * (std::abs(NdotV) * std::sqrt(a2 + (1 - a2) * NdotL * NdotL) +
                               std::abs(NdotL) * std::sqrt(a2 + (1 - a2) * NdotV * NdotV)));
  const double specular_brdf = Vis * D;
  const double diffuse_brdf = base / kPi;
  const double w = std::pow(1 - std::abs(VdotH), 5);
  // fresnel_mix(f0_color, ior, weight, base, layer) of KHR_materials_specular (grey f0_color).
  const double f0 = std::min(sqr((1 - ior) / (1 + ior)) * specular_color, 1.0);
  const double fr = f0 + (1 - f0) * w;
  const double dielectric = (1 - specular * fr) * diffuse_brdf + specular * fr * specular_brdf;
  const double metal = specular_brdf * (base + (1 - base) * w);
  return mix(dielectric, metal, metallic);
}

TEST(RendererModelsReference, GltfMetallicRoughness) {
  const Model& m = model_by_name("gltf-metallic-roughness");
  struct Set { double metallic, roughness, ior, specular, specular_color; };
  for (Set s : {Set{0.0, 0.5, 1.5, 1.0, 1.0}, Set{1.0, 0.2, 1.5, 1.0, 1.0}, Set{0.3, 0.7, 1.8, 0.6, 2.5}}) {
    const ParamValues v = values_of(m, {{"base_color", 0.8, 0}, {"base_color", 0.3, 1}, {"base_color", 0.05, 2},
                                        {"metallic", s.metallic}, {"roughness", s.roughness}, {"ior", s.ior},
                                        {"specular", s.specular}, {"specular_color", s.specular_color}});
    auto reference = [&m, v](double norm) -> Reference {
      return [&m, v, norm](int c, const Vec3d& wi, const Vec3d& wo) {
        return gltf_brdf(wi, wo, param(m, v, "base_color", c), param(m, v, "metallic", c), param(m, v, "roughness", c),
                         param(m, v, "ior", c), param(m, v, "specular", c), param(m, v, "specular_color", c), norm);
      };
    };
    const std::string label = "metallic=" + std::to_string(s.metallic) + " r=" + std::to_string(s.roughness);
    expect_matches_reference(m, v, reference(kPi), 1e-10, label);
    if (s.metallic == 1.0) expect_detects_five_percent(m, v, reference(kPi / 1.05), 1e-10, label);
  }
}

// ---- Mitsuba 3 ------------------------------------------------------------------------------
double mitsuba_d(bool beckmann, double alpha, const Vec3d& m) {
  const double c2 = m.z() * m.z();
  double r;
  if (beckmann) {
    r = std::exp(-(sqr(m.x() / alpha) + sqr(m.y() / alpha)) / c2) / (kPi * alpha * alpha * c2 * c2);
  } else {
    r = 1 / (kPi * alpha * alpha * sqr(sqr(m.x() / alpha) + sqr(m.y() / alpha) + c2));
  }
  return r * m.z() > 1e-20 ? r : 0.0;
}
double mitsuba_smith_g1(bool beckmann, double alpha, const Vec3d& v, const Vec3d& m) {
  const double xy_alpha_2 = sqr(alpha * v.x()) + sqr(alpha * v.y());
  const double tan_theta_alpha_2 = xy_alpha_2 / sqr(v.z());
  double result;
  if (beckmann) {
    const double a = 1 / std::sqrt(tan_theta_alpha_2), a_sqr = a * a;
    // Mitsuba writes these constants as float literals (3.535f …); their decimal values here.
    result = a >= 1.6 ? 1.0 : (3.535 * a + 2.181 * a_sqr) / (1 + 2.276 * a + 2.577 * a_sqr);
  } else {
    result = 2 / (1 + std::sqrt(1 + tan_theta_alpha_2));
  }
  if (xy_alpha_2 == 0) result = 1;
  if (v.dot(m) * v.z() <= 0) result = 0;
  return result;
}

// Mitsuba's eval(si.wi = V, wo = L) / cosθ(L).
double mitsuba_roughconductor(bool beckmann, const Vec3d& L, const Vec3d& V, double eta, double k, double spec_refl,
                              double alpha, double norm = 4) {
  const Vec3d si_wi = V, wo = L;
  const Vec3d H = (wo + si_wi).normalized();
  const double D = mitsuba_d(beckmann, alpha, H);
  const double G = mitsuba_smith_g1(beckmann, alpha, si_wi, H) * mitsuba_smith_g1(beckmann, alpha, wo, H);
  double result = D * G / (norm * si_wi.z());
  result *= fresnel_complex(si_wi.dot(H), eta, k) * spec_refl;
  return result / wo.z();
}

TEST(RendererModelsReference, MitsubaRoughConductor) {
  for (bool beckmann : {true, false}) {
    const Model& m = model_by_name(beckmann ? "mitsuba-roughconductor-beckmann" : "mitsuba-roughconductor-ggx");
    for (double alpha : {0.08, 0.45}) {
      const ParamValues v = values_of(m, {{"eta", 0.2, 0}, {"eta", 1.1, 1}, {"eta", 2.5, 2}, {"k", 3.9, 0}, {"k", 2.4, 1},
                                          {"k", 0.0, 2}, {"specular_reflectance", 1.0, 0},
                                          {"specular_reflectance", 0.7, 1}, {"specular_reflectance", 0.9, 2},
                                          {"alpha", alpha}});
      auto reference = [&m, v, beckmann](double norm) -> Reference {
        return [&m, v, beckmann, norm](int c, const Vec3d& wi, const Vec3d& wo) {
          return mitsuba_roughconductor(beckmann, wi, wo, param(m, v, "eta", c), param(m, v, "k", c),
                                        param(m, v, "specular_reflectance", c), param(m, v, "alpha", c), norm);
        };
      };
      const std::string label = "alpha=" + std::to_string(alpha);
      expect_matches_reference(m, v, reference(4), 1e-10, label);
      expect_detects_five_percent(m, v, reference(4 / 1.05), 1e-10, label);
    }
  }
}

struct Principled {
  double base, roughness, metallic, specular, sheen, clearcoat, clearcoat_gloss, flatness;
};

// Mitsuba's Principled::eval(si.wi = V, wo = L) for the front side, spec_trans = 0, no tints,
// isotropic, divided by cosθ(L).
double mitsuba_principled(const Principled& p, const Vec3d& L, const Vec3d& V, double spec_scale = 1) {
  const Vec3d si_wi = V, wo = L;
  const double cos_theta_i = si_wi.z(), cos_theta_o = wo.z();
  const double m_eta = 2.0 / (1.0 - std::sqrt(0.08 * p.specular)) - 1.0;
  const double brdf = 1 - p.metallic;
  const double a = std::max(0.001, sqr(p.roughness));  // calc_dist_params, isotropic
  const Vec3d wh = (si_wi + wo).normalized();
  const double F_spec_dielectric = fresnel_dielectric(si_wi.dot(wh), m_eta);
  const double D = mitsuba_d(false, a, wh);
  const double G = mitsuba_smith_g1(false, a, si_wi, wh) * mitsuba_smith_g1(false, a, wo, wh);
  double value = 0;
  if (F_spec_dielectric > 0) {
    // principled_fresnel: metallic · calc_schlick(base_color) + (1 − metallic) F_dielectric.
    const double w = schlick_weight(std::abs(si_wi.dot(wh)));
    const double F_principled = (1 - p.metallic) * F_spec_dielectric + p.metallic * mix(w, 1.0, p.base);
    value += spec_scale * F_principled * D * G / (4 * std::abs(cos_theta_i));
  }
  if (p.clearcoat > 0) {
    const double Fcc = mix(schlick_weight(std::abs(si_wi.dot(wh))), 1.0, 0.04);
    const double ac = mix(0.1, 0.001, p.clearcoat_gloss), ac2 = ac * ac;
    double Dcc = (ac2 - 1) / (kPi * std::log(ac2) * (1 + (ac2 - 1) * sqr(wh.z())));  // GTR1Isotropic::eval
    if (!(Dcc * wh.z() > 1e-20)) Dcc = 0;
    auto smith_ggx1 = [&](const Vec3d& v) {
      const double c2 = sqr(v.z()), tan2 = (1 - c2) / c2;
      return 2 / (1 + std::sqrt(1 + 0.25 * 0.25 * tan2));
    };
    value += p.clearcoat * 0.25 * Fcc * Dcc * smith_ggx1(si_wi) * smith_ggx1(wo) * std::abs(cos_theta_o);
  }
  const double Fo = schlick_weight(std::abs(cos_theta_o)), Fi = schlick_weight(std::abs(cos_theta_i));
  const double f_diff = (1 - 0.5 * Fi) * (1 - 0.5 * Fo);
  const double cos_theta_d = wh.dot(wo);
  const double Rr = 2 * p.roughness * sqr(cos_theta_d);
  const double f_retro = Rr * (Fo + Fi + Fo * Fi * (Rr - 1));
  const double Fss = mix(1.0, Rr / 2, Fo) * mix(1.0, Rr / 2, Fi);
  const double f_ss = 1.25 * (Fss * (1 / (std::abs(cos_theta_o) + std::abs(cos_theta_i)) - 0.5) + 0.5);
  value += brdf * std::abs(cos_theta_o) * p.base / kPi * mix(f_diff + f_retro, f_ss, p.flatness);
  if (p.sheen > 0) value += p.sheen * (1 - p.metallic) * schlick_weight(std::abs(cos_theta_d)) * std::abs(cos_theta_o);
  return value / cos_theta_o;
}

TEST(RendererModelsReference, MitsubaPrincipled) {
  const Model& m = model_by_name("mitsuba-principled");
  for (Principled s : {Principled{0, 0.5, 0.0, 0.5, 0.0, 0.0, 0.0, 0.0}, Principled{0, 0.25, 1.0, 0.5, 0.0, 0.0, 0.0, 0.0},
                       Principled{0, 0.7, 0.3, 0.9, 0.6, 0.8, 0.4, 0.5}}) {
    const ParamValues v = values_of(m, {{"base_color", 0.8, 0}, {"base_color", 0.3, 1}, {"base_color", 0.05, 2},
                                        {"roughness", s.roughness}, {"metallic", s.metallic}, {"specular", s.specular},
                                        {"sheen", s.sheen}, {"clearcoat", s.clearcoat},
                                        {"clearcoat_gloss", s.clearcoat_gloss}, {"flatness", s.flatness}});
    auto reference = [&m, v, s](double spec_scale) -> Reference {
      return [&m, v, s, spec_scale](int c, const Vec3d& wi, const Vec3d& wo) {
        Principled p = s;
        p.base = param(m, v, "base_color", c);
        return mitsuba_principled(p, wi, wo, spec_scale);
      };
    };
    const std::string label = "metallic=" + std::to_string(s.metallic) + " r=" + std::to_string(s.roughness);
    expect_matches_reference(m, v, reference(1), 1e-10, label);
    if (s.metallic == 1.0) expect_detects_five_percent(m, v, reference(1.05), 1e-10, label);
  }
}

// ---- pbrt-v4 --------------------------------------------------------------------------------
// ConductorBxDF::f(wo = V, wi = L) with TrowbridgeReitzDistribution(α, α), α = sqrt(roughness).
double pbrt_conductor(const Vec3d& L, const Vec3d& V, double roughness, double eta, double k, double norm = kPi) {
  const Vec3d wo = V, wi = L;
  const double alpha = std::sqrt(roughness);
  const Vec3d wm = (wi + wo).normalized();
  const double cos2 = sqr(wm.z()), tan2 = (1 - cos2) / cos2;
  const double e = tan2 * (sqr(wm.x()) / (1 - cos2) / sqr(alpha) + sqr(wm.y()) / (1 - cos2) / sqr(alpha));
  const double D = 1 / (norm * alpha * alpha * sqr(cos2) * sqr(1 + e));
  auto lambda = [&](const Vec3d& w) {
    const double c2 = sqr(w.z()), t2 = (1 - c2) / c2;
    return (std::sqrt(1 + alpha * alpha * t2) - 1) / 2;
  };
  const double G = 1 / (1 + lambda(wo) + lambda(wi));
  const double F = fresnel_complex(std::abs(wo.dot(wm)), eta, k);
  return D * F * G / (4 * wi.z() * wo.z());
}
double pbrt_k_of_reflectance(double r) {
  r = std::clamp(r, 0.0, 0.9999);
  return 2 * std::sqrt(r) / std::sqrt(1 - r);
}

TEST(RendererModelsReference, PbrtConductors) {
  const Model& m = model_by_name("pbrt-conductor");
  const Model& mr = model_by_name("pbrt-conductor-reflectance");
  for (double roughness : {0.004, 0.09, 0.5}) {
    const ParamValues v = values_of(m, {{"eta", 0.2, 0}, {"eta", 1.1, 1}, {"eta", 2.5, 2}, {"k", 3.9, 0}, {"k", 2.4, 1},
                                        {"k", 0.0, 2}, {"roughness", roughness}});
    auto reference = [&m, v](double norm) -> Reference {
      return [&m, v, norm](int c, const Vec3d& wi, const Vec3d& wo) {
        return pbrt_conductor(wi, wo, param(m, v, "roughness", c), param(m, v, "eta", c), param(m, v, "k", c), norm);
      };
    };
    const std::string label = "roughness=" + std::to_string(roughness);
    expect_matches_reference(m, v, reference(kPi), 1e-10, label);
    expect_detects_five_percent(m, v, reference(kPi / 1.05), 1e-10, label);

    const ParamValues vr = values_of(mr, {{"reflectance", 0.95, 0}, {"reflectance", 0.5, 1}, {"reflectance", 0.04, 2},
                                          {"roughness", roughness}});
    auto reference_r = [&mr, vr](double norm) -> Reference {
      return [&mr, vr, norm](int c, const Vec3d& wi, const Vec3d& wo) {
        return pbrt_conductor(wi, wo, param(mr, vr, "roughness", c), 1.0,
                              pbrt_k_of_reflectance(param(mr, vr, "reflectance", c)), norm);
      };
    };
    expect_matches_reference(mr, vr, reference_r(kPi), 1e-10, label);
    expect_detects_five_percent(mr, vr, reference_r(kPi / 1.05), 1e-10, label);
  }
}

TEST(RendererModelsReference, PbrtDiffuseAndMix) {
  const Model& d = model_by_name("pbrt-diffuse");
  const ParamValues vd = values_of(d, {{"reflectance", 0.9, 0}, {"reflectance", 0.4, 1}, {"reflectance", 0.05, 2}});
  expect_matches_reference(
      d, vd, [&d, vd](int c, const Vec3d&, const Vec3d&) { return param(d, vd, "reflectance", c) / kPi; }, 1e-14,
      "R/pi");

  const Model& m = model_by_name("pbrt-mix-diffuse-conductor");
  for (double amount : {0.2, 0.85}) {
    const ParamValues v = values_of(m, {{"reflectance", 0.6, 0}, {"reflectance", 0.3, 1}, {"reflectance", 0.1, 2},
                                        {"amount", amount}, {"conductor_reflectance", 0.9, 0},
                                        {"conductor_reflectance", 0.5, 1}, {"conductor_reflectance", 0.2, 2},
                                        {"roughness", 0.05}});
    auto reference = [&m, v](double norm) -> Reference {
      return [&m, v, norm](int c, const Vec3d& wi, const Vec3d& wo) {
        const double amt = param(m, v, "amount", c);
        const double f1 = pbrt_conductor(wi, wo, param(m, v, "roughness", c), 1.0,
                                         pbrt_k_of_reflectance(param(m, v, "conductor_reflectance", c)), norm);
        return (1 - amt) * param(m, v, "reflectance", c) / kPi + amt * f1;
      };
    };
    const std::string label = "amount=" + std::to_string(amount);
    expect_matches_reference(m, v, reference(kPi), 1e-10, label);
    if (amount > 0.5) expect_detects_five_percent(m, v, reference(kPi / 1.05), 1e-10, label);
  }
}

// ---- Disney BRDF Explorer -----------------------------------------------------------------------
struct Disney {
  double baseColor, metallic, subsurface, specular, roughness, sheen, clearcoat, clearcoatGloss;
};
double disney_brdf(const Disney& p, const Vec3d& L, const Vec3d& V, double norm = kPi) {
  const Vec3d N(0, 0, 1), X(1, 0, 0), Y(0, 1, 0);
  const double NdotL = N.dot(L), NdotV = N.dot(V);
  if (NdotL < 0 || NdotV < 0) return 0;
  const Vec3d H = (L + V).normalized();
  const double NdotH = N.dot(H), LdotH = L.dot(H);
  const double Cdlin = std::pow(p.baseColor, 2.2);
  const double Cspec0 = mix(p.specular * .08, Cdlin, p.metallic);  // specularTint = 0
  const double FL = schlick_weight(NdotL), FV = schlick_weight(NdotV);
  const double Fd90 = 0.5 + 2 * LdotH * LdotH * p.roughness;
  const double Fd = mix(1, Fd90, FL) * mix(1, Fd90, FV);
  const double Fss90 = LdotH * LdotH * p.roughness;
  const double Fss = mix(1, Fss90, FL) * mix(1, Fss90, FV);
  const double ss = 1.25 * (Fss * (1 / (NdotL + NdotV) - .5) + .5);
  const double aspect = 1;  // anisotropic = 0
  const double ax = std::max(.001, sqr(p.roughness) / aspect), ay = std::max(.001, sqr(p.roughness) * aspect);
  const double Ds = 1 / (norm * ax * ay * sqr(sqr(H.dot(X) / ax) + sqr(H.dot(Y) / ay) + NdotH * NdotH));
  const double FH = schlick_weight(LdotH);
  const double Fs = mix(Cspec0, 1, FH);
  auto smithG_GGX_aniso = [&](double NdotW, double WdotX, double WdotY) {
    return 1 / (NdotW + std::sqrt(sqr(WdotX * ax) + sqr(WdotY * ay) + sqr(NdotW)));
  };
  const double Gs = smithG_GGX_aniso(NdotL, L.dot(X), L.dot(Y)) * smithG_GGX_aniso(NdotV, V.dot(X), V.dot(Y));
  const double Fsheen = FH * p.sheen;  // sheenTint = 0
  const double a = mix(.1, .001, p.clearcoatGloss);
  const double Dr = a >= 1 ? 1 / kPi : (a * a - 1) / (kPi * std::log(a * a) * (1 + (a * a - 1) * NdotH * NdotH));
  const double Fr = mix(.04, 1, FH);
  auto smithG_GGX = [](double NdotW, double alphaG) {
    const double aa = alphaG * alphaG, b = NdotW * NdotW;
    return 1 / (NdotW + std::sqrt(aa + b - aa * b));
  };
  const double Gr = smithG_GGX(NdotL, .25) * smithG_GGX(NdotV, .25);
  return ((1 / kPi) * mix(Fd, ss, p.subsurface) * Cdlin + Fsheen) * (1 - p.metallic) + Gs * Fs * Ds +
         .25 * p.clearcoat * Gr * Fr * Dr;
}

TEST(RendererModelsReference, DisneyPrincipled) {
  const Model& m = model_by_name("disney-principled");
  for (Disney s : {Disney{0, 0.0, 0.0, 0.5, 0.5, 0.0, 0.0, 1.0}, Disney{0, 1.0, 0.0, 0.5, 0.3, 0.0, 0.0, 1.0},
                   Disney{0, 0.4, 0.6, 0.8, 0.7, 0.5, 0.9, 0.3}}) {
    const ParamValues v = values_of(m, {{"baseColor", 0.82, 0}, {"baseColor", 0.67, 1}, {"baseColor", 0.16, 2},
                                        {"metallic", s.metallic}, {"subsurface", s.subsurface}, {"specular", s.specular},
                                        {"roughness", s.roughness}, {"sheen", s.sheen}, {"clearcoat", s.clearcoat},
                                        {"clearcoatGloss", s.clearcoatGloss}});
    auto reference = [&m, v, s](double norm) -> Reference {
      return [&m, v, s, norm](int c, const Vec3d& wi, const Vec3d& wo) {
        Disney p = s;
        p.baseColor = param(m, v, "baseColor", c);
        return disney_brdf(p, wi, wo, norm);
      };
    };
    const std::string label = "metallic=" + std::to_string(s.metallic) + " r=" + std::to_string(s.roughness);
    expect_matches_reference(m, v, reference(kPi), 1e-10, label);
    if (s.metallic == 1.0) expect_detects_five_percent(m, v, reference(kPi / 1.05), 1e-10, label);
  }
}

}  // namespace
}  // namespace brdfkit::test::ref
