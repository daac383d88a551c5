#include "brdfkit/measured/merl_row_cells.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "brdfkit/core/vector_kernel.h"
#include "brdfkit/measured/merl.h"

namespace brdfkit::merl {

namespace {

constexpr std::size_t kBlock = 256;

// The half-difference angles of a block of pairs of one incidence (Rusinkiewicz 1998: d is wi in
// the frame of h, to_half_diff's rotations by −φh about z then −θh about y written with h's own
// components). The callers pad the block, so no value goes through a scalar remainder loop.
BRDFKIT_VECTOR_KERNEL void half_diff_block(double wix, double wiy, double wiz, const double* __restrict ox,
                                           const double* __restrict oy, const double* __restrict oz,
                                           double* __restrict theta_h, double* __restrict theta_d,
                                           double* __restrict phi_d) {
  for (std::size_t k = 0; k < kBlock; ++k) {
    const double vx = wix + ox[k], vy = wiy + oy[k], vz = wiz + oz[k];
    const double norm = std::sqrt(vx * vx + vy * vy + vz * vz);  // Eigen's normalized(), as to_half_diff
    const double hx = vx / norm, hy = vy / norm, hz = vz / norm;
    theta_h[k] = acos(std::clamp(hz, -1.0, 1.0));
    const double rho = std::sqrt(hx * hx + hy * hy);
    const bool on_axis = !(rho > 0);  // φh = atan2(0, 0) = 0
    const double cos_phi = on_axis ? 1.0 : hx / rho, sin_phi = on_axis ? 0.0 : hy / rho;
    const double tx = cos_phi * wix + sin_phi * wiy, ty = cos_phi * wiy - sin_phi * wix;
    const double dx = tx * hz - wiz * rho, dz = tx * rho + wiz * hz;
    theta_d[k] = acos(std::clamp(dz, -1.0, 1.0));
    phi_d[k] = atan2(ty, dx);
  }
}

// cell_of(θh, θd, φd)'s offset for each angle of a block, with merl.cpp's index rules in their own
// arithmetic, and whether the pair must go through cell_of(wi, wo) instead (`exact`): θd below 1e-4,
// where φd is ill-conditioned, or an index coordinate within 1e-6 of a cell edge, where the angles'
// rounding (under 1e-9 in index units for θd ≥ 1e-4) could move its floor. A loop of its own: in
// half_diff_block's, GCC threads the acos clamps into these tests and leaves the loop scalar.
BRDFKIT_VECTOR_KERNEL void cells_block(const double* __restrict theta_h, const double* __restrict theta_d,
                                       const double* __restrict phi_d, std::int32_t* __restrict offset,
                                       double* __restrict exact) {
  for (std::size_t k = 0; k < kBlock; ++k) {
    const double phi = phi_d[k] < 0.0 ? phi_d[k] + kPi : phi_d[k];
    // theta_h_index, theta_d_index and phi_d_index's coordinates (measured/merl.cpp).
    const double th = std::sqrt(theta_h[k] / (kPi / 2.0) * kResThetaH * kResThetaH);
    const double td = theta_d[k] / (kPi * 0.5) * kResThetaD, tp = phi / kPi * kResPhiD;
    // They are ≥ 0 (θh, θd from acos, φ ∈ [0, π]), so each rule's clamps come down to one upper
    // bound, taken as a double before a conversion that no condition guards (a guarded one keeps
    // the loop scalar). int32: the conversions AVX2 and AVX-512F vectorize (offsets < 1.5·10⁶).
    const std::int32_t ih = std::int32_t(th < kResThetaH - 1 ? th : kResThetaH - 1.0),
                       id = std::int32_t(td < kResThetaD - 1 ? td : kResThetaD - 1.0),
                       ip = std::int32_t(tp < kResPhiD - 1 ? tp : kResPhiD - 1.0);
    offset[k] = ip + kResPhiD * (id + kResThetaD * ih);
    // The distance of the index coordinates (cell edges at integers) to the nearest edge.
    const double xh = kResThetaH * std::sqrt(theta_h[k] / (kPi / 2));
    const double fh = xh - double(std::int32_t(xh)), fd = td - double(std::int32_t(td)),
                 fp = tp - double(std::int32_t(tp));
    const double edge = std::min({fh, 1.0 - fh, fd, 1.0 - fd, fp, 1.0 - fp});
    exact[k] = theta_d[k] < 1e-4 || edge < 1e-6 ? 1.0 : 0.0;  // a double: 64-bit lanes like the tests
  }
}

}  // namespace

void row_cells(const Vec3d& wi, std::span<const Vec3d> wo, std::vector<size_t>& out) {
  out.assign(wo.size(), kNoCell);
  if (!(wi.z() > 0)) return;
  alignas(64) double ox[kBlock], oy[kBlock], oz[kBlock], theta_h[kBlock], theta_d[kBlock], phi_d[kBlock];
  alignas(64) double exact[kBlock];
  alignas(64) std::int32_t offset[kBlock];
  for (std::size_t b = 0; b < wo.size(); b += kBlock) {
    const std::size_t n = std::min(kBlock, wo.size() - b);
    for (std::size_t k = 0; k < kBlock; ++k) {
      const Vec3d& o = k < n ? wo[b + k] : wi;  // padding: a valid pair
      ox[k] = o.x();
      oy[k] = o.y();
      oz[k] = o.z();
    }
    half_diff_block(wi.x(), wi.y(), wi.z(), ox, oy, oz, theta_h, theta_d, phi_d);
    cells_block(theta_h, theta_d, phi_d, offset, exact);
    for (std::size_t k = 0; k < n; ++k)
      if (wo[b + k].z() > 0) out[b + k] = exact[k] != 0 ? cell_offset(cell_of(wi, wo[b + k])) : size_t(offset[k]);
  }
}

}  // namespace brdfkit::merl
