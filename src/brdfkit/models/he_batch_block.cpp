#include "brdfkit/models/he_batch_block.h"

#include <algorithm>
#include <cmath>

#include "brdfkit/core/vector_kernel.h"
#include "brdfkit/models/he_torrance.h"

namespace brdfkit {

BRDFKIT_VECTOR_KERNEL void he_channel_block(const double* p, int c, const HeBlockPairs& __restrict pairs,
                                            HeBlockChannel& __restrict out) {
  // A copy, so that no store to `out` could change a parameter inside the loop.
  double q[HeTorrance::kK + 1];
  std::copy(p, p + HeTorrance::kK + 1, q);
  for (std::size_t k = 0; k < kHeBlock; ++k) {
    const HeTorrance::Unsummed<double> u =
        HeTorrance::unsummed_of(q, c, pairs.vv[k], pairs.vz[k], pairs.vxy2[k], pairs.sigma[k], pairs.geometry[k],
                                pairs.shadow[k], pairs.den[k]);
    out.g[k] = u.g;
    out.c[k] = u.c;
    out.front[k] = u.front;
  }
  out.scale = HeTorrance::series_scale(p, c);
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
