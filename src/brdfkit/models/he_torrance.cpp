#include "brdfkit/models/he_torrance.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <vector>

#include "brdfkit/core/warp.h"
#include "brdfkit/models/he_batch_block.h"
#include "brdfkit/models/lobe_mixture.h"
#include "brdfkit/ndf/beckmann.h"

namespace brdfkit {

namespace {

// S(θi)S(θr) and σ, which depend on a pair's two cosines alone, for the pairs of a block: a pair
// whose cosines are the previous pair's takes its values (a metric's grid varies Δφ fastest, so
// there they change once per row), the others are computed kHePairLanes at a time.
class PairShapes {
 public:
  explicit PairShapes(const double* p) : sigma0_(p[HeTorrance::kSigma0]), tau_(p[HeTorrance::kTau]) {}

  // shadow[k] and sigma[k] of the pairs k < m that have above[k].
  void fill(const bool* above, const double* cos_i, const double* cos_o, std::size_t m, double* shadow,
            double* sigma) {
    constexpr std::size_t kCarried = kHeBlock;  // the last pair of an earlier block
    std::size_t fresh[kHeBlock], source[kHeBlock], n = 0, from = kCarried;
    for (std::size_t k = 0; k < m; ++k) {
      if (!above[k]) continue;
      if (!(cos_i[k] == last_i_ && cos_o[k] == last_o_)) {
        last_i_ = cos_i[k];
        last_o_ = cos_o[k];
        fresh[n++] = from = k;
      }
      source[k] = from;
    }
    for (std::size_t first = 0; first < n; first += kHePairLanes)
      compute(fresh + first, std::min(kHePairLanes, n - first), cos_i, cos_o, shadow, sigma);
    for (std::size_t k = 0; k < m; ++k) {
      if (!above[k] || source[k] == k) continue;
      shadow[k] = source[k] == kCarried ? last_shadow_ : shadow[source[k]];
      sigma[k] = source[k] == kCarried ? last_sigma_ : sigma[source[k]];
    }
    for (std::size_t k = m; k-- > 0;)
      if (above[k]) {
        last_shadow_ = shadow[k];
        last_sigma_ = sigma[k];
        break;
      }
  }

 private:
  // The pairs index[0 … count) (count ≤ kHePairLanes) through the vector lanes, padded with the
  // first; a pair with a cosine below kHePairMinCos through the scalar terms.
  void compute(const std::size_t* index, std::size_t count, const double* cos_i, const double* cos_o,
               double* shadow, double* sigma) const {
    double ci[kHePairLanes], co[kHePairLanes], s[kHePairLanes], g[kHePairLanes];
    for (std::size_t l = 0; l < kHePairLanes; ++l) {
      const std::size_t k = index[l < count ? l : 0];
      const bool lanes = cos_i[k] >= kHePairMinCos && cos_o[k] >= kHePairMinCos;
      ci[l] = lanes ? cos_i[k] : 1.0;
      co[l] = lanes ? cos_o[k] : 1.0;
    }
    he_pair_shape_lanes(sigma0_, tau_, ci, co, s, g);
    for (std::size_t l = 0; l < count; ++l) {
      const std::size_t k = index[l];
      if (cos_i[k] >= kHePairMinCos && cos_o[k] >= kHePairMinCos) {
        shadow[k] = s[l];
        sigma[k] = g[l];
        continue;
      }
      const HeSlopeTerms<double> si(cos_i[k], sigma0_, tau_), so(cos_o[k], sigma0_, tau_);
      shadow[k] = si.shadowing * so.shadowing;                                  // Eq. 23
      sigma[k] = he_effective_roughness_of(si.k_factor + so.k_factor, sigma0_);  // Eq. 80
    }
  }

  double sigma0_, tau_;
  double last_i_ = std::numeric_limits<double>::quiet_NaN(), last_o_ = last_i_;  // equal to no cosine
  double last_shadow_ = 0, last_sigma_ = 0;
};

// ρ of `count` channels (p[i]: the parameters of channel channel[i], all with the σ0 and τ of
// p[0]) at n pairs, block by block: the shape terms pair by pair, once for every channel
// (PairShapes), then each channel's Eq. 75 but the series (he_channel_block) and the series
// (HeSeriesTable::block_at, the table's rows once for every channel) of the whole block at once,
// then the products.
void eval_channels(const double* const* p, const int* channel, int count, std::size_t n, const double* wi_x,
                   const double* wi_y, const double* wi_z, const double* wo_x, const double* wo_y, const double* wo_z,
                   double* const* out) {
  const HeSeriesTable& table = HeSeriesTable::get();
  PairShapes shapes(p[0]);
  const double tau = p[0][HeTorrance::kTau];
  HeBlockPairs pairs{};  // lanes no pair fills are read (and their values dropped) by he_pair_block
  HeSeriesTable::Rows rows;
  HeBlockChannel lanes[3];
  bool above[kHeBlock];
  // Channels whose η and k are channel 0's to the bit share its F G S.
  bool same_fresnel[3] = {true, false, false};
  for (int i = 1; i < count; ++i)
    same_fresnel[i] = std::memcmp(p[i] + HeTorrance::kEta, p[0] + HeTorrance::kEta, 2 * sizeof(double)) == 0;
  for (std::size_t start = 0; start < n; start += kHeBlock) {
    const std::size_t m = std::min(kHeBlock, n - start);
    for (std::size_t k = 0; k < kHeBlock; ++k) above[k] = k < m && wi_z[start + k] > 0 && wo_z[start + k] > 0;
    shapes.fill(above, wi_z + start, wo_z + start, m, pairs.shadow, pairs.sigma);
    he_pair_block(tau, above, m, wi_x + start, wi_y + start, wi_z + start, wo_x + start, wo_y + start, wo_z + start,
                  pairs);
    table.rows(pairs.ratio, rows);
    for (int i = 0; i < count; ++i) {
      HeBlockChannel& l = lanes[i];
      he_channel_block(p[i], channel[i], pairs, i > 0 && same_fresnel[i] ? lanes[0].front : nullptr, l);
      table.block_at(rows, l.g, l.series);
      he_rho_block(p[i], l, pairs, above, m, out[i] + start);
    }
  }
}

}  // namespace

void HeTorrance::eval_batch(const double* p, int c, std::size_t n, const double* wi_x, const double* wi_y,
                            const double* wi_z, const double* wo_x, const double* wo_y, const double* wo_z,
                            double* out) {
  eval_channels(&p, &c, 1, n, wi_x, wi_y, wi_z, wo_x, wo_y, wo_z, &out);
}

void HeTorrance::eval_batch_rgb(const double* const p[3], std::size_t n, const double* wi_x, const double* wi_y,
                                const double* wi_z, const double* wo_x, const double* wo_y, const double* wo_z,
                                double* const out[3]) {
  for (int c = 1; c < 3; ++c)
    if (!(p[c][kSigma0] == p[0][kSigma0] && p[c][kTau] == p[0][kTau])) {
      for (int ch = 0; ch < 3; ++ch) eval_batch(p[ch], ch, n, wi_x, wi_y, wi_z, wo_x, wo_y, wo_z, out[ch]);
      return;
    }
  static constexpr int kRgb[3] = {0, 1, 2};
  eval_channels(p, kRgb, 3, n, wi_x, wi_y, wi_z, wo_x, wo_y, wo_z, out);
}

bool HeTorrance::eval_batch_from(const double* p, const double* p0, const double* at_p0, int c, std::size_t n,
                                 const double* wi_x, const double* wi_y, const double* wi_z, const double* wo_x,
                                 const double* wo_y, const double* wo_z, double* out) {
  for (int j : {kKd, kKs, kSigma0, kTau})
    if (!(p[j] == p0[j])) return false;
  std::vector<double> f0(n);
  he_fresnel_ratio_block(p, p0, at_p0, n, wi_x, wi_y, wi_z, wo_x, wo_y, wo_z, out, f0.data());
  // Below the horizon 0; where the ratio does not serve, eval_batch. dd0 = ρ(p0) − kd/π carries
  // the rounding of kd/π: where it is under 1e-3 of it, the ratio would magnify that.
  const double diffuse = p[kKd] * kInvPi;
  std::vector<std::size_t> index;
  for (std::size_t k = 0; k < n; ++k) {
    if (!(wi_z[k] > 0 && wo_z[k] > 0)) out[k] = 0;
    else if (!(f0[k] > 0 && std::abs(at_p0[k] - diffuse) >= 1e-3 * diffuse)) index.push_back(k);
  }
  if (index.empty()) return true;
  const std::size_t m = index.size();
  std::vector<double> rest(7 * m);  // those pairs' six coordinates, then their ρ
  const double* from[6] = {wi_x, wi_y, wi_z, wo_x, wo_y, wo_z};
  for (int a = 0; a < 6; ++a)
    for (std::size_t i = 0; i < m; ++i) rest[size_t(a) * m + i] = from[a][index[i]];
  double* rho = rest.data() + 6 * m;
  eval_batch(p, c, m, rest.data(), rest.data() + m, rest.data() + 2 * m, rest.data() + 3 * m, rest.data() + 4 * m,
             rest.data() + 5 * m, rho);
  for (std::size_t i = 0; i < m; ++i) out[index[i]] = rho[i];
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
