#pragma once
// Ward 1992 (as compared in seed 002): ρ = kd/π + ks exp(−tan²θh (cos²φh/αx² + sin²φh/αy²))
// / (4π αx αy sqrt(cosθi cosθo)) (DESIGN.md §6). `ward` is the isotropic form (αx = αy = α),
// `ward-aniso` the anisotropic one with x = the tangent of the local frame.
// Reciprocal: every factor is symmetric in (wi, wo).
//
// Sampling: kd/π cosine-weighted, or the half vector from the Gaussian slope density the lobe
// is built on (Walter 2005, "Notes on the Ward BRDF", Eq. 6–9), mixed by kd : ks.
#include <array>
#include <cmath>
#include <optional>
#include <string_view>

#include "brdfkit/core/warp.h"
#include "brdfkit/models/lobe_mixture.h"
#include "brdfkit/core/param.h"

namespace brdfkit {

namespace ward_detail {

// tan²θh (cos²φh/αx² + sin²φh/αy²) from the unnormalized half vector h = wi + wo: the
// tangent components over hz are the slopes, so no angle is ever formed.
template <class T> T exponent(const Vec3<T>& h, const T& ax, const T& ay) {
  const T sx = h.x() / (ax * h.z()), sy = h.y() / (ay * h.z());
  return sx * sx + sy * sy;
}

// Half vector with density exp(−(sx²/αx² + sy²/αy²)) / (π αx αy cos³θh) over solid angle:
// a Gaussian in slope space (dω = cos³θh d²s), drawn by the Box-Muller radius r² = −ln(1 − u).
inline Vec3d sample_half(double ax, double ay, const Vec2d& u) {
  const double r = std::sqrt(-std::log1p(-u.x()));
  const double phi = 2 * kPi * u.y();
  const Vec3d m(-ax * r * std::cos(phi), -ay * r * std::sin(phi), 1.0);
  return m.normalized();
}
inline double half_pdf(double ax, double ay, const Vec3d& h) {
  if (!(h.z() > 0)) return 0.0;
  const double c3 = h.z() * h.z() * h.z();
  return std::exp(-exponent<double>(h, ax, ay)) / (kPi * ax * ay * c3);
}

// kd/π + lobe mixture shared by Ward, anisotropic Ward and Ward-Duer; ks is the lobe's
// albedo estimate (exact at normal incidence for small α).
inline std::optional<Vec3d> sample(double kd, double ks, double ax, double ay, const Vec3d& wo, const Vec2d& u,
                                   double u_lobe) {
  const auto prob = lobes::selection_probabilities<2>({kd, ks});
  if (lobes::pick(prob, u_lobe) == 0) return square_to_cosine_hemisphere(u);
  return lobes::reflect_about_half(wo, sample_half(ax, ay, u));
}
inline double pdf(double kd, double ks, double ax, double ay, const Vec3d& wo, const Vec3d& wi) {
  if (!(wi.z() > 0 && wo.z() > 0)) return 0.0;
  const auto prob = lobes::selection_probabilities<2>({kd, ks});
  const double spec = lobes::half_vector_pdf(wo, wi, [&](const Vec3d& h) { return half_pdf(ax, ay, h); });
  return prob[0] * cosine_hemisphere_pdf(wi) + prob[1] * spec;
}

}  // namespace ward_detail

struct Ward {
  static std::string_view name() { return "ward"; }
  static std::string_view description() {
    return "Lambert + isotropic Ward 1992, ks exp(-tan^2 th/a^2)/(4 pi a^2 sqrt(cos_i cos_o))";
  }
  static constexpr bool kReciprocal = true;
  static ParamTable params() {
    return {{"kd", 0.0, 1.0, 0.5, Scope::PerChannel, true, "diffuse albedo (Lambertian kd/pi)"},
            {"ks", 0.0, 1.0, 0.1, Scope::PerChannel, true, "specular scale (Ward 1992 rho_s)"},
            {"alpha", 1e-3, 1.0, 0.1, Scope::Shared, false, "Ward width, sqrt(2) x RMS slope (Ward 1992)"}};
  }
  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    using std::exp;
    using std::sqrt;
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    const T& a = p[2];
    const Vec3<T> h = wi + wo;
    // DESIGN.md §6 (Ward 1992 Eq. 5a, isotropic).
    const T spec = p[1] * exp(-ward_detail::exponent<T>(h, a, a)) / (T(4 * kPi) * a * a * sqrt(wi.z() * wo.z()));
    return p[0] * T(kInvPi) + spec;
  }
  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double u_lobe) {
    return ward_detail::sample(p[0], p[1], p[2], p[2], wo, u, u_lobe);
  }
  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    return ward_detail::pdf(p[0], p[1], p[2], p[2], wo, wi);
  }
};

struct WardAniso {
  static std::string_view name() { return "ward-aniso"; }
  static std::string_view description() {
    return "Lambert + anisotropic Ward 1992, widths alpha_x (tangent) and alpha_y (bitangent)";
  }
  static constexpr bool kReciprocal = true;
  static ParamTable params() {
    return {{"kd", 0.0, 1.0, 0.5, Scope::PerChannel, true, "diffuse albedo (Lambertian kd/pi)"},
            {"ks", 0.0, 1.0, 0.1, Scope::PerChannel, true, "specular scale (Ward 1992 rho_s)"},
            {"alpha_x", 1e-3, 1.0, 0.1, Scope::Shared, false, "Ward width along the tangent x (Ward 1992)"},
            {"alpha_y", 1e-3, 1.0, 0.1, Scope::Shared, false, "Ward width along the bitangent y (Ward 1992)"}};
  }
  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    using std::exp;
    using std::sqrt;
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    const Vec3<T> h = wi + wo;
    // DESIGN.md §6 (Ward 1992 Eq. 5a).
    const T spec =
        p[1] * exp(-ward_detail::exponent<T>(h, p[2], p[3])) / (T(4 * kPi) * p[2] * p[3] * sqrt(wi.z() * wo.z()));
    return p[0] * T(kInvPi) + spec;
  }
  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double u_lobe) {
    return ward_detail::sample(p[0], p[1], p[2], p[3], wo, u, u_lobe);
  }
  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    return ward_detail::pdf(p[0], p[1], p[2], p[3], wo, wi);
  }
};

}  // namespace brdfkit
