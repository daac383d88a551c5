#pragma once
// Sampling helpers shared by the "kd/π + specular lobe(s)" models of the catalogue (ward.h,
// ward_duer.h, blinn_phong_lobe.h, lafortune.h, ashikhmin_shirley.h, low_smooth.h).
//
// A mixture picks one component with probability proportional to its albedo estimate
// (DESIGN.md §6, seed 004 §5.5), draws from it, and reports the mixture density
// Σ wⱼ pⱼ(wi) / Σ wⱼ, so any estimate is unbiased; a better estimate only lowers variance.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/warp.h"

namespace brdfkit::lobes {

// Selection probabilities from non-negative weights; all-zero weights select uniformly, so
// the pdf never vanishes where a component with zero weight still has support.
template <std::size_t K> std::array<double, K> selection_probabilities(std::array<double, K> w) {
  double sum = 0;
  for (double& x : w) {
    x = std::isfinite(x) ? std::max(0.0, x) : 0.0;
    sum += x;
  }
  for (double& x : w) x = sum > 0 ? x / sum : 1.0 / double(K);
  return w;
}

// Index of the component u_lobe ∈ [0, 1) falls into.
template <std::size_t K> std::size_t pick(const std::array<double, K>& prob, double u_lobe) {
  double acc = 0;
  for (std::size_t j = 0; j + 1 < K; ++j) {
    acc += prob[j];
    if (u_lobe < acc) return j;
  }
  return K - 1;
}

// Mirror of wo about the half vector h; nullopt when wo is behind h or wi leaves the hemisphere
// (that mass is the sampler's deficit, DESIGN.md §6 "Half-vector sampling").
inline std::optional<Vec3d> reflect_about_half(const Vec3d& wo, const Vec3d& h) {
  const double oh = wo.dot(h);
  if (!(oh > 0)) return std::nullopt;
  const Vec3d wi = reflect(wo, h);
  if (!(wi.z() > 0)) return std::nullopt;
  return wi;
}

// Density over wi of "draw h with density ph(h) over solid angle, reflect wo about h":
// pdf(wi) = ph(h) / (4 |wo·h|) (Walter et al. 2007 Eq. 14; DESIGN.md §6).
template <class HalfPdf> double half_vector_pdf(const Vec3d& wo, const Vec3d& wi, HalfPdf&& ph) {
  if (!(wi.z() > 0 && wo.z() > 0)) return 0.0;
  const Vec3d sum = wi + wo;
  const double len = sum.norm();
  if (!(len > 0)) return 0.0;
  const Vec3d h = sum / len;
  const double oh = wo.dot(h);
  if (!(oh > 0 && h.z() > 0)) return 0.0;
  return ph(h) / (4.0 * oh);
}

// Direction with density (N+1)/(2π) cosᴺα about +z (the normalized cosine-power lobe:
// ∫ cosᴺα dω = 2π/(N+1)); cosα = u^{1/(N+1)} inverts its CDF.
inline Vec3d sample_cosine_power(double n, const Vec2d& u) {
  const double cos_a = std::pow(1.0 - u.x(), 1.0 / (n + 1.0));  // 1 − u keeps u = 0 off cosα = 0
  const double sin_a = std::sqrt(std::max(0.0, 1.0 - cos_a * cos_a));
  const double phi = 2 * kPi * u.y();
  return Vec3d(sin_a * std::cos(phi), sin_a * std::sin(phi), cos_a);
}
inline double cosine_power_pdf(double n, double cos_a) {
  return cos_a > 0 ? (n + 1.0) / (2 * kPi) * std::pow(cos_a, n) : 0.0;
}

}  // namespace brdfkit::lobes
