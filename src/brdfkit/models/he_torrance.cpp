#include "brdfkit/models/he_torrance.h"

#include <algorithm>
#include <array>
#include <limits>

#include "brdfkit/core/warp.h"
#include "brdfkit/models/lobe_mixture.h"
#include "brdfkit/ndf/beckmann.h"

namespace brdfkit {

void HeTorrance::eval_batch(const double* p, int c, std::size_t n, const double* wi_x, const double* wi_y,
                            const double* wi_z, const double* wo_x, const double* wo_y, const double* wo_z,
                            double* out) {
  double cached_cos = std::numeric_limits<double>::quiet_NaN();  // equal to no cosine
  HeSlopeTerms<double> slope_i;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3d wi(wi_x[k], wi_y[k], wi_z[k]), wo(wo_x[k], wo_y[k], wo_z[k]);
    if (!(wi.z() > 0 && wo.z() > 0)) {
      out[k] = 0;
      continue;
    }
    if (!(wi.z() == cached_cos)) {
      slope_i = HeSlopeTerms<double>(wi.z(), p[kSigma0], p[kTau]);
      cached_cos = wi.z();
    }
    const HeSlopeTerms<double> slope_o(wo.z(), p[kSigma0], p[kTau]);
    out[k] = p[kKd] * kInvPi + p[kKs] * directional_diffuse_with(p, c, wi, wo, slope_i, slope_o);
  }
}

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
