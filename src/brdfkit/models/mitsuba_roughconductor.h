#pragma once
// Mitsuba 3's `roughconductor` BSDF (mitsuba-renderer/mitsuba3 v3.9.1, src/bsdfs/roughconductor.cpp
// eval(), include/mitsuba/render/microfacet.h, include/mitsuba/render/fresnel.h), isotropic:
//   ρ = specular_reflectance · F(wi·h; eta, k) · D(h) · G1(wi) G1(wo) / (4 cosθi cosθo)
// (Mitsuba's eval returns ρ cosθ of the light direction: D G F / (4 cosθ of the other one)).
//   D Beckmann: exp(−((hx/α)² + (hy/α)²)/hz²) / (π α² hz⁴);  GGX: 1 / (π α² ((hx/α)² + (hy/α)² + hz²)²),
//     both set to 0 where D cosθh ≤ 1e-20 (MicrofacetDistribution::eval)
//   G1 Beckmann: Walter et al. 2007's rational approximation, a = 1/(α tanθ):
//     (3.535 a + 2.181 a²) / (1 + 2.276 a + 2.577 a²), 1 for a ≥ 1.6 — not the exact erfc form;
//   G1 GGX: 2 / (1 + sqrt(1 + α² tan²θ)); both 1 at normal incidence (smith_g1)
//   F: the exact unpolarized conductor Fresnel (fresnel_conductor), fresnel/conductor.h's form.
// `distribution` defaults to beckmann in Mitsuba (DESIGN.md §14): an export must write it.
// α is clamped to ≥ 1e-4 by Mitsuba (MicrofacetDistribution::configure); the bounds stay above it.
// In a spectral variant Mitsuba upsamples RGB eta and k to spectra: ρ per RGB channel is what an
// RGB variant (scalar_rgb, llvm_ad_rgb) computes.
#include <optional>
#include <string_view>

#include "brdfkit/core/param.h"
#include "brdfkit/core/vec.h"
#include "brdfkit/fresnel/conductor.h"
#include "brdfkit/models/renderer_sampling.h"
#include "brdfkit/ndf/beckmann.h"
#include "brdfkit/ndf/ggx.h"

namespace brdfkit {

enum class MitsubaDistribution { Beckmann, Ggx };

namespace mitsuba_detail {

// MicrofacetDistribution::eval, isotropic, for a unit half vector h.
template <class T> T microfacet_d(MitsubaDistribution type, const T& alpha, const Vec3<T>& h) {
  using std::exp;
  const T c2 = h.z() * h.z();
  const T sx = h.x() / alpha, sy = h.y() / alpha;
  T d;
  if (type == MitsubaDistribution::Beckmann) {
    d = exp(-(sx * sx + sy * sy) / c2) / (T(kPi) * alpha * alpha * c2 * c2);
  } else {
    const T s = sx * sx + sy * sy + c2;
    d = T(1) / (T(kPi) * alpha * alpha * s * s);
  }
  return d * h.z() > T(1e-20) ? d : T(0);
}

// MicrofacetDistribution::smith_g1 for a direction v above the horizon with v·h > 0.
template <class T> T smith_g1(MitsubaDistribution type, const T& alpha, const Vec3<T>& v) {
  using std::sqrt;
  const T xy_alpha_2 = alpha * alpha * (v.x() * v.x() + v.y() * v.y());
  if (!(xy_alpha_2 > T(0))) return T(1);  // perpendicular incidence
  const T tan_theta_alpha_2 = xy_alpha_2 / (v.z() * v.z());
  if (type == MitsubaDistribution::Beckmann) {
    const T a = T(1) / sqrt(tan_theta_alpha_2), a2 = a * a;
    if (a >= T(1.6)) return T(1);
    return (T(3.535) * a + T(2.181) * a2) / (T(1) + T(2.276) * a + T(2.577) * a2);
  }
  return T(2) / (T(1) + sqrt(T(1) + tan_theta_alpha_2));
}

}  // namespace mitsuba_detail

template <MitsubaDistribution kType> struct MitsubaRoughConductor {
  static std::string_view name() {
    return kType == MitsubaDistribution::Beckmann ? "mitsuba-roughconductor-beckmann" : "mitsuba-roughconductor-ggx";
  }
  static std::string_view description() {
    return kType == MitsubaDistribution::Beckmann
               ? "Mitsuba 3 roughconductor, distribution beckmann (v3.9.1 roughconductor.cpp)"
               : "Mitsuba 3 roughconductor, distribution ggx (v3.9.1 roughconductor.cpp)";
  }
  static constexpr bool kReciprocal = true;
  enum Index { kEta, kK, kSpecularReflectance, kAlpha };
  static ParamTable params() {
    return {{"eta", 0.01, 10.0, 1.5, Scope::PerChannel, false, "real part of the complex IOR (Mitsuba eta)"},
            {"k", 0.0, 10.0, 1.0, Scope::PerChannel, false, "imaginary part of the complex IOR (Mitsuba k)"},
            {"specular_reflectance", 0.0, 1.0, 1.0, Scope::PerChannel, true,
             "factor on the specular reflection (Mitsuba specular_reflectance)"},
            {"alpha", 1e-3, 1.5, 0.1, Scope::Shared, false,
             "microfacet alpha as Mitsuba takes it (no remapping; Beckmann: sqrt(2) x RMS slope)"}};
  }

  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    const Vec3<T> h = (wi + wo).normalized();
    const T& alpha = p[kAlpha];
    const T d = mitsuba_detail::microfacet_d(kType, alpha, h);
    const T g = mitsuba_detail::smith_g1(kType, alpha, wi) * mitsuba_detail::smith_g1(kType, alpha, wo);
    const T f = ConductorFresnel<T>(p + kEta).eval(wi.dot(h));
    return p[kSpecularReflectance] * f * d * g / (T(4) * wi.z() * wo.z());
  }

  template <class Ndf> static std::optional<Vec3d> sample_with(const Ndf& ndf, const Vec3d& wo, const Vec2d& u) {
    if (!(wo.z() > 0)) return std::nullopt;
    return lobes::reflect_about_half(wo, ndf.sample(u));
  }
  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double) {
    if constexpr (kType == MitsubaDistribution::Beckmann) return sample_with(Beckmann<double>(p + kAlpha), wo, u);
    else return sample_with(Ggx<double>(p + kAlpha), wo, u);
  }
  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    auto density = [&](const Vec3d& h) {
      if constexpr (kType == MitsubaDistribution::Beckmann) return Beckmann<double>(p + kAlpha).pdf(h);
      else return Ggx<double>(p + kAlpha).pdf(h);
    };
    return lobes::half_vector_pdf(wo, wi, density);
  }
};

using MitsubaRoughConductorBeckmann = MitsubaRoughConductor<MitsubaDistribution::Beckmann>;
using MitsubaRoughConductorGgx = MitsubaRoughConductor<MitsubaDistribution::Ggx>;

}  // namespace brdfkit
