#pragma once
// Ashikhmin-Shirley 2000 specular lobe, isotropic (nu = nv = N), as compared in seed 002:
// ρ = kd/π + (N+1)/(8π) cosᴺθh / ((wi·h) max(cosθi, cosθo)) · F(wi·h)   (DESIGN.md §6).
// `ashikhmin-shirley`: F = Schlick with F0 = Rs per channel (Ashikhmin-Shirley 2000 Eq. 5),
// which is also the lobe's colour. `ashikhmin-shirley-dielectric`: ks per channel times the
// Cook-Torrance dielectric F(wi·h; η), the form of Löw 2012's published fits (their
// `conventions`). `ashikhmin-shirley-ngan2005`: seed 002's form (§3.1, a specular colour times a
// lobe shape shared by the channels), ks per channel times Schlick F(wi·h; F0) with one F0, as
// Ngan's published fits define it (published-fits/ngan2005/README.md). Reciprocal: wi·h = wo·h
// and the max is symmetric.
// Sampling: the half vector with density (N+1)/(2π) cosᴺθh (Ashikhmin-Shirley 2000 §3).
#include <cmath>
#include <optional>
#include <string_view>

#include "brdfkit/core/warp.h"
#include "brdfkit/fresnel/dielectric.h"
#include "brdfkit/fresnel/schlick.h"
#include "brdfkit/models/lobe_mixture.h"
#include "brdfkit/core/param.h"

namespace brdfkit {

namespace as_detail {

// (N+1)/(8π) cosᴺθh / ((wi·h) max(cosθi, cosθo)) without the Fresnel factor; sets wi·h.
template <class T> T lobe(const T& n, const Vec3<T>& wi, const Vec3<T>& wo, T& wi_dot_h) {
  using std::pow;
  const Vec3<T> hs = wi + wo;
  const T len = hs.norm();
  const Vec3<T> h = hs / len;
  wi_dot_h = wi.dot(h);
  const T mx = wi.z() > wo.z() ? wi.z() : wo.z();
  return (n + T(1)) / T(8 * kPi) * pow(h.z(), n) / (wi_dot_h * mx);  // DESIGN.md §6
}

inline std::optional<Vec3d> sample(double w_diffuse, double w_spec, double n, const Vec3d& wo, const Vec2d& u,
                                   double u_lobe) {
  const auto prob = lobes::selection_probabilities<2>({w_diffuse, w_spec});
  if (lobes::pick(prob, u_lobe) == 0) return square_to_cosine_hemisphere(u);
  return lobes::reflect_about_half(wo, lobes::sample_cosine_power(n, u));
}
inline double pdf(double w_diffuse, double w_spec, double n, const Vec3d& wo, const Vec3d& wi) {
  if (!(wi.z() > 0 && wo.z() > 0)) return 0.0;
  const auto prob = lobes::selection_probabilities<2>({w_diffuse, w_spec});
  const double spec = lobes::half_vector_pdf(wo, wi, [n](const Vec3d& h) { return lobes::cosine_power_pdf(n, h.z()); });
  return prob[0] * cosine_hemisphere_pdf(wi) + prob[1] * spec;
}

}  // namespace as_detail

struct AshikhminShirley {
  static std::string_view name() { return "ashikhmin-shirley"; }
  static std::string_view description() {
    return "Lambert + isotropic Ashikhmin-Shirley 2000 lobe with Schlick Fresnel (F0 = Rs)";
  }
  static constexpr bool kReciprocal = true;
  static ParamTable params() {
    return {{"kd", 0.0, 1.0, 0.5, Scope::PerChannel, true, "diffuse albedo (Lambertian kd/pi)"},
            {"Rs", 0.0, 1.0, 0.05, Scope::PerChannel, false, "specular reflectance at normal incidence, Schlick F0 (AS 2000)"},
            {"N", 0.0, 1e7, 100.0, Scope::Shared, false, "Phong-like exponent nu = nv (sharpness)", 0.0, kUnbounded}};
  }
  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    T cos_d;
    const T s = as_detail::lobe(p[2], wi, wo, cos_d);
    return p[0] * T(kInvPi) + s * SchlickFresnel<T>(p + 1).eval(cos_d);
  }
  // The specular weight is F at the mirror configuration (wi·h = cosθo), a rough albedo.
  static double spec_weight(const double* p, const Vec3d& wo) { return SchlickFresnel<double>(p + 1).eval(wo.z()); }
  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double u_lobe) {
    return as_detail::sample(p[0], spec_weight(p, wo), p[2], wo, u, u_lobe);
  }
  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    return as_detail::pdf(p[0], spec_weight(p, wo), p[2], wo, wi);
  }
};

struct AshikhminShirleyDielectric {
  static std::string_view name() { return "ashikhmin-shirley-dielectric"; }
  static std::string_view description() {
    return "Lambert + isotropic Ashikhmin-Shirley lobe, ks x Cook-Torrance dielectric Fresnel (Low 2012 fits)";
  }
  static constexpr bool kReciprocal = true;
  static ParamTable params() {
    // Löw 2012's published fits reach ks = 1.82 and N = 6.2e5 (published-fits/low2012-ashikhminshirley-*.json).
    return {{"kd", 0.0, 1.0, 0.5, Scope::PerChannel, true, "diffuse albedo (Lambertian kd/pi)"},
            {"ks", 0.0, 5.0, 1.0, Scope::PerChannel, true, "specular scale (Low 2012's specular 'albedo')"},
            {"N", 0.0, 1e7, 100.0, Scope::Shared, false, "Phong-like exponent nu = nv (Low 2012's 'sharpness')", 0.0,
             kUnbounded},
            {"eta", 1.0, 100.0, 1.5, Scope::Shared, false, "Fresnel parameter eta (Cook-Torrance dielectric, Low 2012)",
             1.0, kUnbounded}};
  }
  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    T cos_d;
    const T s = as_detail::lobe(p[2], wi, wo, cos_d);
    return p[0] * T(kInvPi) + p[1] * s * DielectricFresnel<T>(p + 3).eval(cos_d);
  }
  static double spec_weight(const double* p, const Vec3d& wo) {
    return p[1] * DielectricFresnel<double>(p + 3).eval(wo.z());
  }
  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double u_lobe) {
    return as_detail::sample(p[0], spec_weight(p, wo), p[2], wo, u, u_lobe);
  }
  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    return as_detail::pdf(p[0], spec_weight(p, wo), p[2], wo, wi);
  }
};

struct AshikhminShirleyNgan {
  static std::string_view name() { return "ashikhmin-shirley-ngan2005"; }
  static std::string_view description() {
    return "Lambert + isotropic Ashikhmin-Shirley lobe, ks x Schlick F(F0): seed 002's form (Ngan 2005 fits)";
  }
  static constexpr bool kReciprocal = true;
  enum Index { kKd, kKs, kN, kF0 };
  static ParamTable params() {
    return {{"kd", 0.0, 1.0, 0.5, Scope::PerChannel, true, "diffuse albedo (Lambertian kd/pi)"},
            {"ks", 0.0, 1.0, 0.1, Scope::PerChannel, true, "specular colour (Ngan 2005's specular 'albedo')"},
            {"N", 0.0, 1e7, 100.0, Scope::Shared, false, "Phong-like exponent nu = nv (Ngan 2005's 'sharpness')", 0.0,
             kUnbounded},
            {"F0", 0.0, 1.0, 0.05, Scope::Shared, false, "Schlick F0 shared by the channels (Ngan 2005's 'fresnelReflectance')"}};
  }
  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    T cos_d;
    const T s = as_detail::lobe(p[kN], wi, wo, cos_d);
    return p[kKd] * T(kInvPi) + p[kKs] * s * SchlickFresnel<T>(p + kF0).eval(cos_d);
  }
  static double spec_weight(const double* p, const Vec3d& wo) {
    return p[kKs] * SchlickFresnel<double>(p + kF0).eval(wo.z());
  }
  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double u_lobe) {
    return as_detail::sample(p[kKd], spec_weight(p, wo), p[kN], wo, u, u_lobe);
  }
  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    return as_detail::pdf(p[kKd], spec_weight(p, wo), p[kN], wo, wi);
  }
};

}  // namespace brdfkit
