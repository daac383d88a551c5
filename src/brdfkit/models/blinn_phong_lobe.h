#pragma once
// Blinn-Phong half-vector lobe (Blinn 1977, as compared in seed 002 §4.5):
// ρ = kd/π + ks (N+2)/(8π) cosᴺθh.
// The constant is brdfkit's convention (DESIGN.md §6): with the Blinn-Phong distribution
// D = (N+2)/(2π) cosᴺθh (seed 001 Table 1) it is ks D/4, i.e. a microfacet lobe with
// F G/(cosθi cosθo) = 1, so ks ≈ the albedo at normal incidence for large N. Ngan's own
// constant is in his supplemental, not in the seeds: convert explicitly when comparing.
// Reciprocal. Sampled by the half vector with density (N+1)/(2π) cosᴺθh.
#include <cmath>
#include <optional>
#include <string_view>

#include "brdfkit/core/warp.h"
#include "brdfkit/models/lobe_mixture.h"
#include "brdfkit/core/param.h"

namespace brdfkit {

struct BlinnPhongLobe {
  static std::string_view name() { return "blinn-phong"; }
  static std::string_view description() { return "Lambert + Blinn-Phong half-vector lobe, ks (N+2)/(8 pi) cos^N th"; }
  static constexpr bool kReciprocal = true;
  static ParamTable params() {
    return {{"kd", 0.0, 1.0, 0.5, Scope::PerChannel, true, "diffuse albedo (Lambertian kd/pi)"},
            {"ks", 0.0, 1.0, 0.1, Scope::PerChannel, true, "specular scale, ~ albedo at normal incidence (DESIGN.md 6)"},
            {"N", 0.0, 1e6, 50.0, Scope::Shared, false, "Blinn-Phong exponent (sharpness)", 0.0, kUnbounded}};
  }
  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    using std::pow;
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    const Vec3<T> h = wi + wo;
    const T cos_h = h.z() / h.norm();
    // DESIGN.md §6 (brdfkit's Blinn-Phong constant).
    return p[0] * T(kInvPi) + p[1] * (p[2] + T(2)) / T(8 * kPi) * pow(cos_h, p[2]);
  }
  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double u_lobe) {
    const auto prob = lobes::selection_probabilities<2>({p[0], p[1]});
    if (lobes::pick(prob, u_lobe) == 0) return square_to_cosine_hemisphere(u);
    return lobes::reflect_about_half(wo, lobes::sample_cosine_power(p[2], u));
  }
  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    if (!(wi.z() > 0 && wo.z() > 0)) return 0.0;
    const auto prob = lobes::selection_probabilities<2>({p[0], p[1]});
    const double n = p[2];
    const double spec = lobes::half_vector_pdf(wo, wi, [n](const Vec3d& h) { return lobes::cosine_power_pdf(n, h.z()); });
    return prob[0] * cosine_hemisphere_pdf(wi) + prob[1] * spec;
  }
};

}  // namespace brdfkit
