#include "brdfkit/models/he_torrance.h"

#include <algorithm>
#include <array>

#include "brdfkit/core/warp.h"
#include "brdfkit/models/lobe_mixture.h"
#include "brdfkit/ndf/beckmann.h"

namespace brdfkit {

double HeTorrance::specular_reflectance(const double* p, int c, double cos_i) {
  if (!(cos_i > 0)) return 0.0;
  const double sigma0 = p[kSigma0], tau = p[kTau];
  const double k = 2 * kPi / wavelength_um(c);
  const double sigma = he_effective_roughness(cos_i, cos_i, sigma0, tau);
  const double kg = k * sigma * 2 * cos_i;  // Eq. 79 at θr = θi
  const double s = he_shadowing(cos_i, sigma0, tau);
  return p[kKs] * ConductorFresnel<double>(p + kEta).eval(cos_i) * std::exp(-kg * kg) * s * s;  // Eq. 74
}

double HeTorrance::lobe_alpha(const double* p, int c) {
  const double rough = 2 * p[kSigma0] / p[kTau];
  const double smooth = wavelength_um(c) / (2 * kPi * p[kTau]);
  return std::clamp(std::hypot(rough, smooth), 1e-3, 4.0);
}

namespace {

// Selection weights: kd, and the directional-diffuse albedo estimated as the part of the
// Fresnel reflectance the spike does not take at θo (energy balance of He 1991 §5).
std::array<double, 2> probabilities(const double* p, int c, const Vec3d& wo) {
  const double co = std::clamp(wo.z(), 0.0, 1.0);
  const double k = 2 * kPi / HeTorrance::wavelength_um(c);
  const double kg = k * p[HeTorrance::kSigma0] * 2 * co;
  const double dd = p[HeTorrance::kKs] * ConductorFresnel<double>(p + HeTorrance::kEta).eval(co) * -std::expm1(-kg * kg);
  return lobes::selection_probabilities<2>({p[HeTorrance::kKd], dd});
}

}  // namespace

std::optional<Vec3d> HeTorrance::sample(const double* p, int c, const Vec3d& wo, const Vec2d& u, double u_lobe) {
  if (!(wo.z() > 0)) return std::nullopt;
  const auto prob = probabilities(p, c, wo);
  if (lobes::pick(prob, u_lobe) == 0) return square_to_cosine_hemisphere(u);
  const double alpha = lobe_alpha(p, c);
  return lobes::reflect_about_half(wo, Beckmann<double>(&alpha).sample(u));
}

double HeTorrance::pdf(const double* p, int c, const Vec3d& wo, const Vec3d& wi) {
  if (!(wi.z() > 0 && wo.z() > 0)) return 0.0;
  const auto prob = probabilities(p, c, wo);
  const double alpha = lobe_alpha(p, c);
  const Beckmann<double> lobe(&alpha);
  const double spec = lobes::half_vector_pdf(wo, wi, [&](const Vec3d& h) { return lobe.pdf(h); });
  return prob[0] * cosine_hemisphere_pdf(wi) + prob[1] * spec;
}

}  // namespace brdfkit
