#pragma once
// He's directional-diffuse term (he_torrance.h, Eq. 75) on many pairs at once, as vector
// instructions: what one channel computes of each pair of a block from the pair's shape terms
// (eval_batch), and the Fresnel ratio of eval_batch_from.
#include <cstddef>

#include "brdfkit/models/he_series_table.h"

namespace brdfkit {

inline constexpr std::size_t kHeBlock = HeSeriesTable::kBlock;

// The shape terms of a block's pairs (HeTorrance::PairTerms' numbers), den = π cosθi cosθr, and
// the series' c/g (HeTorrance::series_ratio).
struct HeBlockPairs {
  double vv[kHeBlock], vz[kHeBlock], vxy2[kHeBlock], sigma[kHeBlock], geometry[kHeBlock], shadow[kHeBlock],
      den[kHeBlock], ratio[kHeBlock];
};

// One channel's part of Eq. 75 at each pair of a block: the series' arguments g and c, the factor
// in front of it, and the series once looked up.
struct HeBlockChannel {
  double g[kHeBlock], c[kHeBlock], front[kHeBlock], series[kHeBlock];
  double scale = 0;  // Eq. 78's factor, the same at every pair
};

// What depends on a pair's two cosines alone, kHePairLanes pairs at once: S(θi)S(θr) (he_shadowing.h,
// Eq. 23–25) and the effective roughness σ (he_effective_roughness.h, Eq. 80–83), with glibc's
// vector erfc and exp and the vector Lambert W of he_z0_ratio_lanes. Within 1e-14 relative of
// HeSlopeTerms and he_effective_roughness_of (tests/models/he/test_he_components.cpp) for
// cosines in [kHePairMinCos, 1]; below it σ's f0 could overflow f0², and the caller takes the scalar terms.
inline constexpr std::size_t kHePairLanes = 8;
inline constexpr double kHePairMinCos = 1e-100;
void he_pair_shape_lanes(double sigma0, double tau, const double* cos_i, const double* cos_o, double* shadow,
                         double* sigma);

// x = sqrt(W0(f0²)), the root of x e^{x²/2} = f0 (he_effective_roughness.h), at kHePairLanes values
// f0 in [0, 1e150]: Winitzki's approximation of W0 polished by two Halley steps, within 1e-15 of
// Boost's lambert_w0 (tests/models/he/test_he_components.cpp). Boost's is scalar; this one runs
// on vector exp and log1p.
void he_z0_ratio_lanes(const double* f0, double* x);

// The pairs' numbers of HeTorrance::pair_terms, den (as HeTorrance::unsummed) and c/g
// (HeTorrance::series_ratio) at the pairs k < m of a block with above[k], from their directions and
// the shadow and sigma already in `pairs`: the same arithmetic to the bit. Every other lane takes
// the numbers of wi = wo = ẑ with σ = 1 (a series the table covers: g = 4k²); its value is not used.
void he_pair_block(double tau, const bool* above, std::size_t m, const double* wi_x, const double* wi_y,
                   const double* wi_z, const double* wo_x, const double* wo_y, const double* wo_z, HeBlockPairs& pairs);

// HeTorrance::unsummed_of at every pair of the block, for channel c with parameters p: the same
// arithmetic to the bit (no libm call: square roots and divisions are exact in any width). With
// `front` given (an earlier channel's, whose η and k are p's), its F G S is taken from there.
void he_channel_block(const double* p, int c, const HeBlockPairs& pairs, const double* front, HeBlockChannel& out);

// ρ = kd/π + ks · Unsummed::of(series) at the pairs k < m of a block with above[k], 0 at the
// others (HeTorrance::eval): plain arithmetic, the same to the bit.
void he_rho_block(const double* p, const HeBlockChannel& channel, const HeBlockPairs& pairs, const bool* above,
                  std::size_t m, double* out);

// HeTorrance::eval_batch_from's ratio at n pairs: out[k] = d + (at_p0[k] − d) F_p / F_p0 with
// d = kd/π, and f0[k] = F_p0, at every pair, the caller choosing where the ratio serves. The same
// arithmetic as HeTorrance's to the bit.
void he_fresnel_ratio_block(const double* p, const double* p0, const double* at_p0, std::size_t n, const double* wi_x,
                            const double* wi_y, const double* wi_z, const double* wo_x, const double* wo_y,
                            const double* wo_z, double* out, double* f0);

}  // namespace brdfkit
