#include "brdfkit/models/he_torrance.h"

#include <algorithm>
#include <array>
#include <limits>

#include "brdfkit/core/warp.h"
#include "brdfkit/models/lobe_mixture.h"
#include "brdfkit/ndf/beckmann.h"

namespace brdfkit {

namespace {

// A value kept while the input it is a function of repeats: the same bits as computing it anew.
template <class V> class KeptValue {
 public:
  template <class F> const V& at(double input, F&& compute) {
    if (!(input == input_)) {
      value_ = compute(input);
      input_ = input;
    }
    return value_;
  }

 private:
  double input_ = std::numeric_limits<double>::quiet_NaN();  // equal to no input
  V value_{};
};

// Calls pair(k, wi, wo, terms) for the pairs above the horizon and below(k) for the others. The
// slope terms of wi and wo are kept while their cosines repeat and σ while Ki + Kr repeats.
template <class Pair, class Below>
void for_each_pair(const double* p, std::size_t n, const double* wi_x, const double* wi_y, const double* wi_z,
                   const double* wo_x, const double* wo_y, const double* wo_z, Pair&& pair, Below&& below) {
  const double sigma0 = p[HeTorrance::kSigma0], tau = p[HeTorrance::kTau];
  auto slope = [&](double cos_theta) { return HeSlopeTerms<double>(cos_theta, sigma0, tau); };
  KeptValue<HeSlopeTerms<double>> slope_i, slope_o;
  KeptValue<double> sigma;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3d wi(wi_x[k], wi_y[k], wi_z[k]), wo(wo_x[k], wo_y[k], wo_z[k]);
    if (!(wi.z() > 0 && wo.z() > 0)) {
      below(k);
      continue;
    }
    const HeSlopeTerms<double>& si = slope_i.at(wi.z(), slope);
    const HeSlopeTerms<double>& so = slope_o.at(wo.z(), slope);
    const double s = sigma.at(si.k_factor + so.k_factor,
                              [&](double k_sum) { return he_effective_roughness_of(k_sum, sigma0); });  // Eq. 80
    pair(k, wi, wo, HeTorrance::pair_terms(wi, wo, si.shadowing * so.shadowing, s));  // Eq. 23
  }
}

// Eq. 78's series from its table (HeTorrance::series for doubles), the column in g kept while g repeats.
class KeptSeries {
 public:
  double operator()(double g, double c) {
    return table_(column_.at(g, [&](double x) { return table_.column(x); }), c);
  }

 private:
  const HeSeriesTable& table_ = HeSeriesTable::get();
  KeptValue<HeSeriesTable::Column> column_;
};

}  // namespace

void HeTorrance::eval_batch(const double* p, int c, std::size_t n, const double* wi_x, const double* wi_y,
                            const double* wi_z, const double* wo_x, const double* wo_y, const double* wo_z,
                            double* out) {
  KeptSeries series;
  for_each_pair(
      p, n, wi_x, wi_y, wi_z, wo_x, wo_y, wo_z,
      [&](std::size_t k, const Vec3d& wi, const Vec3d& wo, const PairTerms<double>& t) {
        out[k] = p[kKd] * kInvPi + p[kKs] * directional_diffuse_by(p, c, wi, wo, t, series);
      },
      [&](std::size_t k) { out[k] = 0; });
}

void HeTorrance::eval_batch_rgb(const double* const p[3], std::size_t n, const double* wi_x, const double* wi_y,
                                const double* wi_z, const double* wo_x, const double* wo_y, const double* wo_z,
                                double* const out[3]) {
  for (int c = 1; c < 3; ++c)
    if (!(p[c][kSigma0] == p[0][kSigma0] && p[c][kTau] == p[0][kTau])) {
      for (int ch = 0; ch < 3; ++ch) eval_batch(p[ch], ch, n, wi_x, wi_y, wi_z, wo_x, wo_y, wo_z, out[ch]);
      return;
    }
  KeptSeries series[3];
  for_each_pair(
      p[0], n, wi_x, wi_y, wi_z, wo_x, wo_y, wo_z,
      [&](std::size_t k, const Vec3d& wi, const Vec3d& wo, const PairTerms<double>& t) {
        for (int c = 0; c < 3; ++c)
          out[c][k] = p[c][kKd] * kInvPi + p[c][kKs] * directional_diffuse_by(p[c], c, wi, wo, t, series[c]);
      },
      [&](std::size_t k) {
        for (int c = 0; c < 3; ++c) out[c][k] = 0;
      });
}

bool HeTorrance::eval_batch_from(const double* p, const double* p0, const double* at_p0, int c, std::size_t n,
                                 const double* wi_x, const double* wi_y, const double* wi_z, const double* wo_x,
                                 const double* wo_y, const double* wo_z, double* out) {
  for (int j : {kKd, kKs, kSigma0, kTau})
    if (!(p[j] == p0[j])) return false;
  const ConductorFresnel<double> fresnel(p + kEta), fresnel0(p0 + kEta);
  const double diffuse = p[kKd] * kInvPi;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3d wi(wi_x[k], wi_y[k], wi_z[k]), wo(wo_x[k], wo_y[k], wo_z[k]);
    if (!(wi.z() > 0 && wo.z() > 0)) {
      out[k] = 0;
      continue;
    }
    // The bisector cosine as directional_diffuse_of computes it.
    const Vec3d v = wi + wo;
    const double vv = (v.x() * v.x() + v.y() * v.y()) + v.z() * v.z();
    const double cos_d = 0.5 * std::sqrt(vv);
    const double f0 = fresnel0.eval(cos_d), dd0 = at_p0[k] - diffuse;
    // dd0 carries the rounding of kd/π: where it is under 1e-3 of it, the ratio would magnify that.
    out[k] = f0 > 0 && std::abs(dd0) >= 1e-3 * diffuse ? diffuse + dd0 * (fresnel.eval(cos_d) / f0)
                                                        : diffuse + p[kKs] * directional_diffuse(p, c, wi, wo);
  }
  return true;
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
