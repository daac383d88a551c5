#pragma once
// pbrt-v4's `conductor` material (mmp/pbrt-v4 at commit 5f7a6068: src/pbrt/materials.h
// ConductorMaterial::GetBxDF, src/pbrt/bxdfs.h ConductorBxDF::f, src/pbrt/util/scattering.h
// TrowbridgeReitzDistribution and FrComplex), isotropic:
//   α = sqrt(roughness)   (RoughnessToAlpha, applied while `remaproughness` is true, the default)
//   D = 1 / (π α² cos⁴θh (1 + tan²θh/α²)²)
//   Λ(w) = (sqrt(1 + α² tan²θ) − 1)/2,  G = 1 / (1 + Λ(wo) + Λ(wi))   height-correlated
//   F = FrComplex(|wo·h|, eta + i k), the exact conductor Fresnel (fresnel/conductor.h's form)
//   ρ = D F G / (4 cosθi cosθo)
// `reflectance` r instead of eta/k: eta = 1, k = 2 sqrt(r) / sqrt(1 − r), r clamped to ≤ 0.9999
// (then F(0) = r). pbrt treats α < 1e-3 as a perfect mirror (EffectivelySmooth): the roughness
// bounds keep α above it. pbrt-v4 renders spectrally: RGB eta, k and reflectance are upsampled to
// spectra (RGBUnboundedSpectrum, RGBAlbedoSpectrum), so ρ per RGB channel is exact for grey
// values and an approximation of pbrt's image for coloured ones.
#include <cmath>
#include <optional>
#include <string_view>

#include "brdfkit/core/param.h"
#include "brdfkit/core/vec.h"
#include "brdfkit/fresnel/conductor.h"
#include "brdfkit/models/lobe_mixture.h"
#include "brdfkit/ndf/ggx.h"

namespace brdfkit {

namespace pbrt_detail {

inline const char* kRoughnessDoc = "pbrt roughness; Trowbridge-Reitz alpha = sqrt(roughness) (remaproughness true)";

// TrowbridgeReitzDistribution::Lambda for a unit direction w.
template <class T> T lambda(const T& alpha, const Vec3<T>& w) {
  using std::sqrt;
  const T s2 = w.x() * w.x() + w.y() * w.y();
  return (sqrt(T(1) + alpha * alpha * s2 / (w.z() * w.z())) - T(1)) / T(2);
}

// ConductorBxDF::f with the complex index (eta, k), wi and wo above the horizon.
template <class T> T conductor_f(const T& roughness, const T& eta, const T& k, const Vec3<T>& wi, const Vec3<T>& wo) {
  using std::sqrt;
  const Vec3<T> h = (wi + wo).normalized();
  const T alpha = sqrt(roughness);
  const T c2 = h.z() * h.z();
  const T e = (T(1) - c2) / (c2 * alpha * alpha);
  const T d = T(1) / (T(kPi) * alpha * alpha * c2 * c2 * (T(1) + e) * (T(1) + e));
  const T g = T(1) / (T(1) + lambda(alpha, wo) + lambda(alpha, wi));
  const T ek[2] = {eta, k};
  const T f = ConductorFresnel<T>(ek).eval(wo.dot(h));
  return d * f * g / (T(4) * wi.z() * wo.z());
}

// ConductorMaterial::GetBxDF's map from `reflectance`: k = 2 sqrt(r) / sqrt(1 − r), eta = 1.
template <class T> T k_from_reflectance(const T& r) {
  using std::sqrt;
  const T rc = r > T(0.9999) ? T(0.9999) : r;
  return T(2) * sqrt(rc) / sqrt(T(1) - rc);
}

// Sampling: the Trowbridge-Reitz D cosθm proposal (pbrt samples visible normals; only the
// value has to match).
inline std::optional<Vec3d> sample_ggx(double roughness, const Vec3d& wo, const Vec2d& u) {
  if (!(wo.z() > 0)) return std::nullopt;
  const double alpha = std::sqrt(roughness);
  return lobes::reflect_about_half(wo, Ggx<double>(&alpha).sample(u));
}
inline double pdf_ggx(double roughness, const Vec3d& wo, const Vec3d& wi) {
  const double alpha = std::sqrt(roughness);
  return lobes::half_vector_pdf(wo, wi, [&](const Vec3d& h) { return Ggx<double>(&alpha).pdf(h); });
}

}  // namespace pbrt_detail

struct PbrtConductor {
  static std::string_view name() { return "pbrt-conductor"; }
  static std::string_view description() { return "pbrt-v4 conductor with eta and k (ConductorBxDF, bxdfs.h)"; }
  static constexpr bool kReciprocal = true;
  enum Index { kEta, kK, kRoughness };
  static ParamTable params() {
    return {{"eta", 0.01, 10.0, 0.2, Scope::PerChannel, false, "pbrt eta (real part of the complex IOR)"},
            {"k", 0.0, 10.0, 3.0, Scope::PerChannel, false, "pbrt k (imaginary part of the complex IOR)"},
            {"roughness", 2e-6, 1.0, 0.01, Scope::Shared, false, pbrt_detail::kRoughnessDoc}};
  }
  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    return pbrt_detail::conductor_f(p[kRoughness], p[kEta], p[kK], wi, wo);
  }
  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double) {
    return pbrt_detail::sample_ggx(p[kRoughness], wo, u);
  }
  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    return pbrt_detail::pdf_ggx(p[kRoughness], wo, wi);
  }
};

struct PbrtConductorReflectance {
  static std::string_view name() { return "pbrt-conductor-reflectance"; }
  static std::string_view description() {
    return "pbrt-v4 conductor with reflectance r (eta 1, k = 2 sqrt(r)/sqrt(1-r); materials.h)";
  }
  static constexpr bool kReciprocal = true;
  enum Index { kReflectance, kRoughness };
  static ParamTable params() {
    return {{"reflectance", 1e-6, 0.9999, 0.5, Scope::PerChannel, false, "pbrt reflectance (normal-incidence F)"},
            {"roughness", 2e-6, 1.0, 0.01, Scope::Shared, false, pbrt_detail::kRoughnessDoc}};
  }
  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    return pbrt_detail::conductor_f(p[kRoughness], T(1), pbrt_detail::k_from_reflectance(p[kReflectance]), wi, wo);
  }
  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double) {
    return pbrt_detail::sample_ggx(p[kRoughness], wo, u);
  }
  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    return pbrt_detail::pdf_ggx(p[kRoughness], wo, wi);
  }
};

}  // namespace brdfkit
