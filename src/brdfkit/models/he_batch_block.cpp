#include "brdfkit/models/he_batch_block.h"

#include <algorithm>
#include <cmath>

#include "brdfkit/core/vector_kernel.h"
#include "brdfkit/models/he_torrance.h"

namespace brdfkit {

namespace {

// W0(z) for z ≥ 0 (w e^w = z): Winitzki 2003's approximation L (1 − log(1 + L)/(2 + L)),
// L = log(1 + z), within 2 % relative, then Halley's iteration for w e^w − z, whose error cubes at
// each step (Corless et al. 1996, Eq. 5.9).
[[gnu::always_inline]] inline double lambert_w0_lane(double z) {
  const double l = log1p(z);
  double w = l * (1 - log1p(l) / (2 + l));
  for (int step = 0; step < 2; ++step) {
    const double ew = exp(w);
    const double f = w * ew - z;
    const double w1 = w + 1;
    w -= f / (ew * w1 - (w + 2) * f / (2 * w1));
  }
  return w;
}

// HeSlope's shadowing and K of one direction (he_shadowing.h), branch-free.
[[gnu::always_inline]] inline void slope_lane(double cos_theta, double sigma0, double tau, double& shadowing,
                                              double& k_factor) {
  const double s2 = 1 - cos_theta * cos_theta;
  const bool oblique = s2 > 1e-24;  // else normal incidence: S = 1, K = 0
  const double tan_theta = std::sqrt(oblique ? s2 : 1.0) / cos_theta;
  const double a = tau / (2 * sigma0 * tan_theta);
  const double erfc_a = erfc(a);
  double lambda = 0.5 * (exp(-a * a) / (std::sqrt(kPi) * a) - erfc_a);  // He 1991 Eq. 25 + errata
  lambda = lambda > 0 ? lambda : 0;
  shadowing = oblique ? (1 - 0.5 * erfc_a) / (lambda + 1) : 1.0;  // He 1991 Eq. 24
  k_factor = oblique ? tan_theta * erfc_a : 0.0;                  // He 1991 Eq. 82–83
}

// The f0 below which x = sqrt(W0(f0²)) = f0 (1 − f0²/2 + …) (W0(z) = z − z² + …) is f0 to the
// last bit: f0²/2 < 2⁻⁵⁴. Most pairs of a smooth surface lie there, K = tanθ erfc(τ/(2σ0 tanθ))
// being tiny away from grazing angles.
constexpr double kZ0Linear = 1e-8;

// x = sqrt(W0(f0²)).
[[gnu::always_inline]] inline double z0_ratio_lane(double f0) {
  const double f = f0 > kZ0Linear ? f0 : 1.0;
  const double root = std::sqrt(lambert_w0_lane(f * f));
  return f0 > kZ0Linear ? root : (f0 > 0 ? f0 : 0.0);
}

}  // namespace

BRDFKIT_VECTOR_KERNEL void he_z0_ratio_lanes(const double* __restrict f0, double* __restrict x) {
  for (std::size_t k = 0; k < kHePairLanes; ++k) x[k] = z0_ratio_lane(f0[k]);
}

BRDFKIT_VECTOR_KERNEL void he_pair_shape_lanes(double sigma0, double tau, const double* __restrict cos_i,
                                               const double* __restrict cos_o, double* __restrict shadow,
                                               double* __restrict sigma) {
  double f0[kHePairLanes], x[kHePairLanes];
  for (std::size_t k = 0; k < kHePairLanes; ++k) {
    double s_i, s_o, k_i, k_o;
    slope_lane(cos_i[k], sigma0, tau, s_i, k_i);
    slope_lane(cos_o[k], sigma0, tau, s_o, k_o);
    shadow[k] = s_i * s_o;                         // He 1991 Eq. 23
    f0[k] = (k_i + k_o) / std::sqrt(8 * kPi);      // He 1991 Eq. 81 divided by σ0
  }
  // Lambert's W only where a lane needs it: z0_ratio_lane's value either way.
  bool linear = true;
  for (std::size_t k = 0; k < kHePairLanes; ++k) linear &= f0[k] <= kZ0Linear;
  if (linear) {
    for (std::size_t k = 0; k < kHePairLanes; ++k) x[k] = f0[k] > 0 ? f0[k] : 0.0;
  } else {
    for (std::size_t k = 0; k < kHePairLanes; ++k) x[k] = z0_ratio_lane(f0[k]);
  }
  for (std::size_t k = 0; k < kHePairLanes; ++k) sigma[k] = sigma0 / std::sqrt(1 + x[k] * x[k]);  // He 1991 Eq. 80
}

BRDFKIT_VECTOR_KERNEL void he_pair_block(double tau, const bool* __restrict above, std::size_t m,
                                         const double* __restrict wi_x, const double* __restrict wi_y,
                                         const double* __restrict wi_z, const double* __restrict wo_x,
                                         const double* __restrict wo_y, const double* __restrict wo_z,
                                         HeBlockPairs& __restrict pairs) {
  for (std::size_t k = 0; k < kHeBlock; ++k) {
    const bool used = k < m && above[k];
    const std::size_t j = used ? k : 0;  // an unused lane reads a pair that exists
    const double vx = wi_x[j] + wo_x[j], vy = wi_y[j] + wo_y[j];
    const double vz = used ? wi_z[j] + wo_z[j] : 2.0;
    const double vxy2 = used ? vx * vx + vy * vy : 0.0;  // HeTorrance::pair_terms
    const double vv = vxy2 + vz * vz;
    const double sigma = used ? pairs.sigma[k] : 1.0;
    pairs.vv[k] = vv;
    pairs.vz[k] = vz;
    pairs.vxy2[k] = vxy2;
    pairs.sigma[k] = sigma;
    pairs.geometry[k] = (vv / vz) * (vv / vz);  // He 1991 Eq. 76 (unpolarized)
    pairs.shadow[k] = used ? pairs.shadow[k] : 1.0;
    pairs.den[k] = used ? kPi * wi_z[j] * wo_z[j] : kPi;
    pairs.ratio[k] = HeTorrance::series_ratio(tau, vxy2, sigma, vz);
  }
}

namespace {

// he_channel_block's loop, F G S computed (front_of) or read from `front`: two loops, so that
// each is a plain vector loop.
template <bool kComputeFront>
[[gnu::always_inline]] inline void channel_lanes(const double* q, int c, const HeBlockPairs& __restrict pairs,
                                                 const double* __restrict front, HeBlockChannel& __restrict out) {
  for (std::size_t k = 0; k < kHeBlock; ++k) {
    const double f = kComputeFront ? HeTorrance::front_of(q, pairs.vv[k], pairs.geometry[k], pairs.shadow[k]) : front[k];
    const HeTorrance::Unsummed<double> u =
        HeTorrance::unsummed_with(q, c, f, pairs.vz[k], pairs.vxy2[k], pairs.sigma[k], pairs.den[k]);
    out.g[k] = u.g;
    out.c[k] = u.c;
    out.front[k] = u.front;
  }
}

}  // namespace

BRDFKIT_VECTOR_KERNEL void he_channel_block(const double* p, int c, const HeBlockPairs& __restrict pairs,
                                            const double* front, HeBlockChannel& __restrict out) {
  // A copy, so that no store to `out` could change a parameter inside the loop.
  double q[HeTorrance::kK + 1];
  std::copy(p, p + HeTorrance::kK + 1, q);
  if (front) channel_lanes<false>(q, c, pairs, front, out);
  else channel_lanes<true>(q, c, pairs, nullptr, out);
  out.scale = HeTorrance::series_scale(p, c);
}

BRDFKIT_VECTOR_KERNEL void he_rho_block(const double* p, const HeBlockChannel& __restrict channel,
                                        const HeBlockPairs& __restrict pairs, const bool* __restrict above,
                                        std::size_t m, double* __restrict out) {
  const double kd_pi = p[HeTorrance::kKd] * kInvPi, ks = p[HeTorrance::kKs];
  for (std::size_t k = 0; k < m; ++k) {
    const HeTorrance::Unsummed<double> u{channel.g[k], channel.c[k], channel.front[k], channel.scale, pairs.den[k]};
    out[k] = above[k] ? kd_pi + ks * u.of(channel.series[k]) : 0.0;
  }
}

BRDFKIT_VECTOR_KERNEL void he_fresnel_ratio_block(const double* p, const double* p0, const double* __restrict at_p0,
                                                  std::size_t n, const double* __restrict wi_x,
                                                  const double* __restrict wi_y, const double* __restrict wi_z,
                                                  const double* __restrict wo_x, const double* __restrict wo_y,
                                                  const double* __restrict wo_z, double* __restrict out,
                                                  double* __restrict f0) {
  const ConductorFresnel<double> fresnel(p + HeTorrance::kEta), fresnel0(p0 + HeTorrance::kEta);
  const double diffuse = p[HeTorrance::kKd] * kInvPi;
  for (std::size_t k = 0; k < n; ++k) {
    // The bisector cosine as HeTorrance::unsummed computes it.
    const double vx = wi_x[k] + wo_x[k], vy = wi_y[k] + wo_y[k], vz = wi_z[k] + wo_z[k];
    const double vv = (vx * vx + vy * vy) + vz * vz;
    const double cos_d = 0.5 * std::sqrt(vv);
    f0[k] = fresnel0.eval(cos_d);
    out[k] = diffuse + (at_p0[k] - diffuse) * (fresnel.eval(cos_d) / f0[k]);
  }
}

}  // namespace brdfkit
