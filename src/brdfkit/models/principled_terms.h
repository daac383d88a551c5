#pragma once
// Terms shared by the Burley-style "principled" models (models/mitsuba_principled.h,
// models/disney_principled.h): Schlick's weight, Burley's GTR1 and lerp, each as both sources
// write them (Mitsuba 3 v3.9.1 src/bsdfs/principledhelpers.h; wdas/brdf src/brdfs/disney.brdf).
#include <cmath>
#include <optional>

#include "brdfkit/core/vec.h"
#include "brdfkit/models/renderer_sampling.h"

namespace brdfkit {

namespace principled_detail {

// (1 − cosθ)⁵ clamped (schlick_weight / Disney's SchlickFresnel).
template <class T> T schlick_weight(const T& c) {
  T m = T(1) - c;
  if (m < T(0)) m = T(0);
  if (m > T(1)) m = T(1);
  const T m2 = m * m;
  return m2 * m2 * m;
}
// Burley's GTR1 (γ = 1): (α² − 1) / (π ln α² (1 + (α² − 1) cos²θh)).
template <class T> T gtr1(const T& cos_h, const T& alpha) {
  using std::log;
  const T a2 = alpha * alpha;
  return (a2 - T(1)) / (T(kPi) * log(a2) * (T(1) + (a2 - T(1)) * cos_h * cos_h));
}
template <class T> T lerp(const T& a, const T& b, const T& t) { return a + t * (b - a); }
// The main lobe's GGX α = max(0.001, roughness²), in both sources.
template <class T> T roughness_alpha(const T& roughness) {
  const T r2 = roughness * roughness;
  return r2 > T(0.001) ? r2 : T(0.001);
}
// The clearcoat lobe for sampling: weight 0.25 · clearcoat · F0 0.04, GTR1's α taken as GGX's.
inline renderer_sampling::HalfLobe<Ggx<double>> clearcoat_lobe(double clearcoat, double gloss) {
  return {0.25 * 0.04 * clearcoat, renderer_sampling::ggx(lerp(0.1, 0.001, gloss))};
}

// Sampling and pdf of a principled model M from its lobes (M::diffuse_weight, M::main_lobe,
// M::clearcoat_lobe), as the renderers' samplers pick them (models/renderer_sampling.h).
template <class M> struct Sampling {
  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double u_lobe) {
    return renderer_sampling::sample(M::diffuse_weight(p), M::main_lobe(p), M::clearcoat_lobe(p), wo, u, u_lobe);
  }
  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    return renderer_sampling::pdf(M::diffuse_weight(p), M::main_lobe(p), M::clearcoat_lobe(p), wo, wi);
  }
};

}  // namespace principled_detail

}  // namespace brdfkit
