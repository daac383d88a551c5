#include "brdfkit/models/holzschuch_pacanowski.h"

#include <algorithm>
#include <cstring>

#include "brdfkit/models/microfacet_model.h"
#include "brdfkit/ndf/d_block.h"

namespace brdfkit {

namespace {

// eval_batch for the channels cs[0], …, cs[channels − 1], whose distribution parameters (σ, p) are
// those of ps[0]: D, the G1 table's coordinates and G1 a block of pairs at a time, once for all of
// them; each channel's ρ from them with eval_with, as eval_batch computes it for that channel alone.
void batch_channels(const double* const* ps, const int* cs, int channels, size_t n, const double* wi_x,
                    const double* wi_y, const double* wi_z, const double* wo_x, const double* wo_y,
                    const double* wo_z, double* const* outs) {
  using HP = HolzschuchPacanowski;
  const ExponentialPower<double> ndf(ps[0] + HP::kNdfOffset);
  const ExponentialPowerG1Table& table = ExponentialPowerG1Table::instance();
  // Per pair k of a block: cosθh, cosθd, σ tanθ of wi and wo, then D and the table coordinates.
  alignas(64) double ch[kDBlock], cd[kDBlock], zi[kDBlock], zo[kDBlock], d[kDBlock], bi[kDBlock], bo[kDBlock];
  for (size_t start = 0; start < n; start += kDBlock) {
    const size_t m = std::min(kDBlock, n - start);
    for (size_t k = 0; k < m; ++k) {
      const size_t j = start + k;
      const double sx = wi_x[j] + wo_x[j], sy = wi_y[j] + wo_y[j], sz = wi_z[j] + wo_z[j];
      const double len = std::sqrt(sx * sx + sy * sy + sz * sz);
      ch[k] = sz / len;
      cd[k] = 0.5 * len;
      zi[k] = HP::slope_scale(ndf.sigma, wi_z[j]);
      zo[k] = HP::slope_scale(ndf.sigma, wo_z[j]);
    }
    std::fill(ch + m, ch + kDBlock, 1.0);  // the padding: any values in the kernels' domains
    std::fill(zi + m, zi + kDBlock, 1.0);
    std::fill(zo + m, zo + kDBlock, 1.0);
    ndf.D_block(ch, d);
    ExponentialPowerG1Table::b_coordinate_block(zi, bi);
    ExponentialPowerG1Table::b_coordinate_block(zo, bo);
    for (size_t k = 0; k < m; ++k) {
      const size_t j = start + k;
      const Vec3d wi(wi_x[j], wi_y[j], wi_z[j]), wo(wo_x[j], wo_y[j], wo_z[j]);
      if (!(wi.z() > 0 && wo.z() > 0)) {
        for (int c = 0; c < channels; ++c) outs[c][j] = 0;
        continue;
      }
      // ExponentialPowerG1Table::g1 with the block's coordinates (1 at the normal).
      const double gi = zi[k] > 0 ? table.g1_at(bi[k], ndf.p) : 1.0, go = zo[k] > 0 ? table.g1_at(bo[k], ndf.p) : 1.0;
      for (int c = 0; c < channels; ++c)
        outs[c][j] = HP::eval_with(ps[c], cs[c], wi, wo, cd[k], d[k], gi * go);  // seed 004 Eq. 7, 24
    }
  }
}

}  // namespace

void HolzschuchPacanowski::eval_batch(const double* p, int c, size_t n, const double* wi_x, const double* wi_y,
                                      const double* wi_z, const double* wo_x, const double* wo_y, const double* wo_z,
                                      double* out) {
  batch_channels(&p, &c, 1, n, wi_x, wi_y, wi_z, wo_x, wo_y, wo_z, &out);
}

void HolzschuchPacanowski::eval_batch_rgb(const double* const p[3], size_t n, const double* wi_x,
                                          const double* wi_y, const double* wi_z, const double* wo_x,
                                          const double* wo_y, const double* wo_z, double* const out[3]) {
  // σ and p, compared bitwise: their terms are shared only where every channel has the same bits.
  const size_t bytes = sizeof(double) * size_t(kA - kNdfOffset);
  if (std::memcmp(p[0] + kNdfOffset, p[1] + kNdfOffset, bytes) == 0 &&
      std::memcmp(p[0] + kNdfOffset, p[2] + kNdfOffset, bytes) == 0) {
    const int channels[3] = {0, 1, 2};
    batch_channels(p, channels, 3, n, wi_x, wi_y, wi_z, wo_x, wo_y, wo_z, out);
    return;
  }
  for (int c = 0; c < 3; ++c) eval_batch(p[c], c, n, wi_x, wi_y, wi_z, wo_x, wo_y, wo_z, out[c]);
}

const Model* holzschuch_pacanowski_model() {
  static const MicrofacetModelAdapter<HolzschuchPacanowski> m;
  return &m;
}

}  // namespace brdfkit
