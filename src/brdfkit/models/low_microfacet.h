#pragma once
// Löw et al. 2012's ABC microfacet model (seed 003 Eq. 15; DESIGN.md §6), registered as
// `low-microfacet`:
//   ρ(wi, wo) = kd/π + A S(θh) F(θd; η) G(wi, wo) / (cosθi cosθo),
//   S = (1 + B(1 − cosθh))^{−C}  (the ABC function of Eq. 11 at ‖x‖² = 1 − cosθh),
// F the Cook-Torrance dielectric Fresnel (fresnel/dielectric.h), G the Cook-Torrance V-groove
// (shadowing/v_groove.h), A·S the unnormalized ABC facet distribution of ndf/abc_facet.h.
// Eq. 15 prints no 1/π on the specular term; Löw's published parameters include one (their
// file's `conventions`): models/published_fits.cpp divides their A by π.
//
// Energy: the model is not energy conserving. G/(cosθi cosθo) grows towards grazing and F → 1,
// so the albedo rises near θ = 90° (seed 003 §5.3 "an increase in reflectance near grazing");
// the published fits reach albedo > 1 there (tests/catalogue_low_hp/test_low_microfacet.cpp
// gives the measured values). Nothing is clamped.
//
// Sampling (seed 003 §4): a mixture of the cosine hemisphere (kd) and the half-vector sampler
// of Eq. 23–28: h with density ∝ S over solid angle (AbcFacet::sample_paper, Eq. 25–26, whose
// C = 1 branch also serves |(1 − C) ln(1 + B)| < 1e-9, the paper's near-1 fallback, written
// there with log1p/expm1 so it is the exact limit), wi = −wo + 2(wo·h)h (Eq. 27), density
// P_h/(4 wo·h) (Eq. 28). Draws below the horizon are rejected (their mass is pdf's deficit).
#include <array>
#include <cmath>
#include <optional>
#include <string_view>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/warp.h"
#include "brdfkit/fresnel/dielectric.h"
#include "brdfkit/models/lobe_mixture.h"
#include "brdfkit/models/model.h"
#include "brdfkit/core/param.h"
#include "brdfkit/ndf/abc_facet.h"
#include "brdfkit/shadowing/v_groove.h"

namespace brdfkit {

struct LowMicrofacet {
  static std::string_view name() { return "low-microfacet"; }
  static std::string_view description() {
    return "Lambert + Low 2012 ABC microfacet model, A (1 + B(1 - cos theta_h))^-C F(theta_d; eta) G / (cos_i cos_o)";
  }
  static constexpr bool kReciprocal = true;
  // Layout of p: kd, then the facet's A, B, C (AbcFacet(p + 1)), then η.
  static constexpr int kFacetOffset = 1;
  static constexpr int kFresnelOffset = 4;

  static ParamTable params() {
    // Löw's published E2 fits span A/π ∈ [0.025, 1817], B ∈ [11.2, 8.1e6], C ∈ [0.024, 2.67],
    // η ∈ [1.04, 99.9996] (published-fits/low2012-microfacet-E2.json); B, C bounds as ndf/abc_facet.h.
    return {{"kd", 0.0, 1.0, 0.2, Scope::PerChannel, true, "diffuse albedo (Lambertian Kd/pi, seed 003 Eq. 15)"},
            {"A", 0.0, 1e4, 1.0, Scope::PerChannel, true, "ABC facet scale A (seed 003 Eq. 15, 11)"},
            {"B", 1e-3, 1e8, 100.0, Scope::Shared, false, "ABC facet sharpness B = b^2 (seed 003 Eq. 11, 15)"},
            {"C", 1e-3, 10.0, 1.0, Scope::Shared, false, "ABC facet fall-off C (seed 003 Eq. 11, 15)"},
            {"eta", 1.0, 100.0, 1.5, Scope::Shared, false,
             "Fresnel parameter eta (Cook-Torrance dielectric, seed 003 Eq. 15)", 1.0, kUnbounded}};
  }

  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    using std::sqrt;
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    const Vec3<T> s = wi + wo;
    const T len = sqrt(s.dot(s));
    // |wi + wo| = 2 cosθd for unit directions: one root for θh and θd, symmetric in (wi, wo).
    const T cos_h = s.z() / len, cos_d = T(0.5) * len;
    const AbcFacet<T> facet(p + kFacetOffset);
    const T spec = facet.D(cos_h) * DielectricFresnel<T>(p + kFresnelOffset).eval(cos_d) * v_groove_g(wi, wo) /
                   (wi.z() * wo.z());  // seed 003 Eq. 15
    return p[0] * T(kInvPi) + spec;
  }

  // Albedo estimate of the specular term, for lobe selection only: with dωi = 4 (wo·h) dωh,
  // (wo·h) ≈ cosθo and G ≈ 1 it is 4 A F(cosθo) ∫ S dω (seed 003 Eq. 24's 1/M_h).
  static double specular_weight(const double* p, const Vec3d& wo) {
    const AbcFacet<double> facet(p + kFacetOffset);
    const double int_s = 2 * kPi * abc_expm1_ratio(1.0 - facet.C, std::log1p(facet.B)) / facet.B;
    return 4 * facet.A * int_s * DielectricFresnel<double>(p + kFresnelOffset).eval(wo.z());
  }
  static std::array<double, 2> probabilities(const double* p, const Vec3d& wo) {
    return lobes::selection_probabilities<2>({p[0], specular_weight(p, wo)});
  }

  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double u_lobe) {
    if (!(wo.z() > 0)) return std::nullopt;
    if (lobes::pick(probabilities(p, wo), u_lobe) == 0) {
      const Vec3d wi = square_to_cosine_hemisphere(u);
      if (!(wi.z() > 0)) return std::nullopt;
      return wi;
    }
    const Vec3d h = AbcFacet<double>(p + kFacetOffset).sample_paper(u);  // seed 003 Eq. 25–26
    return lobes::reflect_about_half(wo, h);                            // Eq. 27
  }

  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    if (!(wi.z() > 0 && wo.z() > 0)) return 0.0;
    const auto prob = probabilities(p, wo);
    const AbcFacet<double> facet(p + kFacetOffset);
    // Eq. 28: P_h / (4 wo·h).
    const double spec = lobes::half_vector_pdf(wo, wi, [&](const Vec3d& h) { return facet.pdf_paper(h); });
    return prob[0] * cosine_hemisphere_pdf(wi) + prob[1] * spec;
  }
};

// The registered runtime instance (low_microfacet.cpp).
const Model* low_microfacet_model();

}  // namespace brdfkit
