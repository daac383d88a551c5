#include "brdfkit/measured/merl_row_cells.h"

#include <algorithm>
#include <cmath>

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

// Whether rounding in the angles could move x's floor: x within 1e-6 of an integer. For θd ≥ 1e-4
// the angles' rounding moves an index coordinate by under 1e-9; a smaller θd goes to cell_of.
bool near_boundary(double x) { return std::abs(x - std::round(x)) < 1e-6; }

// The cell of one pair from its block angles, or cell_of's where a boundary is near. The floor
// rule's coordinates are index_coordinates + ½ up to rounding (~1e-13), far inside the 1e-6.
size_t cell_from_angles(const Vec3d& wi, const Vec3d& wo, double theta_h, double theta_d, double phi_d) {
  const Vec3d x = index_coordinates(theta_h, theta_d, phi_d) + Vec3d::Constant(0.5);  // cell edges at integers
  const bool exact = theta_d < 1e-4 || near_boundary(x[0]) || near_boundary(x[1]) || near_boundary(x[2]);
  return cell_offset(exact ? cell_of(wi, wo) : cell_of(theta_h, theta_d, phi_d));
}

}  // namespace

void row_cells(const Vec3d& wi, std::span<const Vec3d> wo, std::vector<size_t>& out) {
  out.assign(wo.size(), kNoCell);
  if (!(wi.z() > 0)) return;
  alignas(64) double ox[kBlock], oy[kBlock], oz[kBlock], theta_h[kBlock], theta_d[kBlock], phi_d[kBlock];
  for (std::size_t b = 0; b < wo.size(); b += kBlock) {
    const std::size_t n = std::min(kBlock, wo.size() - b);
    for (std::size_t k = 0; k < kBlock; ++k) {
      const Vec3d& o = k < n ? wo[b + k] : wi;  // padding: a valid pair
      ox[k] = o.x();
      oy[k] = o.y();
      oz[k] = o.z();
    }
    half_diff_block(wi.x(), wi.y(), wi.z(), ox, oy, oz, theta_h, theta_d, phi_d);
    for (std::size_t k = 0; k < n; ++k)
      if (wo[b + k].z() > 0) out[b + k] = cell_from_angles(wi, wo[b + k], theta_h[k], theta_d[k], phi_d[k]);
  }
}

}  // namespace brdfkit::merl
