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

// HeTorrance::unsummed_of at every pair of the block, for channel c with parameters p: the same
// arithmetic to the bit (no libm call: square roots and divisions are exact in any width).
void he_channel_block(const double* p, int c, const HeBlockPairs& pairs, HeBlockChannel& out);

// HeTorrance::eval_batch_from's ratio at n pairs: out[k] = d + (at_p0[k] − d) F_p / F_p0 with
// d = kd/π, and f0[k] = F_p0, at every pair, the caller choosing where the ratio serves. The same
// arithmetic as HeTorrance's to the bit.
void he_fresnel_ratio_block(const double* p, const double* p0, const double* at_p0, std::size_t n, const double* wi_x,
                            const double* wi_y, const double* wi_z, const double* wo_x, const double* wo_y,
                            const double* wo_z, double* out, double* f0);

}  // namespace brdfkit
