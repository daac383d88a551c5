#pragma once
// Importance sampling shared by the renderer models (glTF, Mitsuba 3, pbrt-v4, Disney): a cosine
// lobe for the diffuse terms and up to two half-vector lobes (the main microfacet distribution and
// a clearcoat one), picked with probability proportional to an albedo estimate of each
// (models/lobe_mixture.h, DESIGN.md §6). The density reported is the mixture's, so any estimate is
// unbiased. The renderers' own samplers (visible-normal sampling) are not reproduced: only the
// BRDF value has to match them.
#include <array>
#include <optional>

#include "brdfkit/core/warp.h"
#include "brdfkit/models/lobe_mixture.h"
#include "brdfkit/ndf/ggx.h"

namespace brdfkit::renderer_sampling {

// A half-vector lobe: a distribution type with sample(u) (density D cosθm) and pdf(m).
template <class Ndf> struct HalfLobe {
  double weight;  // albedo estimate (clamped at 0 by selection_probabilities)
  Ndf ndf;
};

template <class A, class B>
std::optional<Vec3d> sample(double diffuse_weight, const HalfLobe<A>& a, const HalfLobe<B>& b, const Vec3d& wo,
                            const Vec2d& u, double u_lobe) {
  if (!(wo.z() > 0)) return std::nullopt;
  const auto prob = lobes::selection_probabilities<3>({diffuse_weight, a.weight, b.weight});
  const std::size_t j = lobes::pick(prob, u_lobe);
  if (j == 0) return square_to_cosine_hemisphere(u);
  return lobes::reflect_about_half(wo, j == 1 ? a.ndf.sample(u) : b.ndf.sample(u));
}

template <class A, class B>
double pdf(double diffuse_weight, const HalfLobe<A>& a, const HalfLobe<B>& b, const Vec3d& wo, const Vec3d& wi) {
  if (!(wo.z() > 0 && wi.z() > 0)) return 0.0;
  const auto prob = lobes::selection_probabilities<3>({diffuse_weight, a.weight, b.weight});
  double v = prob[0] * cosine_hemisphere_pdf(wi);
  if (prob[1] > 0) v += prob[1] * lobes::half_vector_pdf(wo, wi, [&](const Vec3d& h) { return a.ndf.pdf(h); });
  if (prob[2] > 0) v += prob[2] * lobes::half_vector_pdf(wo, wi, [&](const Vec3d& h) { return b.ndf.pdf(h); });
  return v;
}

// A GGX lobe of width α (the proposal of every Trowbridge-Reitz term, and of the clearcoat lobes:
// any proposal keeps the mixture density exact).
inline Ggx<double> ggx(double alpha) { return Ggx<double>(&alpha); }

}  // namespace brdfkit::renderer_sampling
