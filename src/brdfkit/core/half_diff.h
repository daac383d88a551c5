#pragma once
// Half/difference angles (Rusinkiewicz 1998) with the rotations of MERL's reference code
// (`std_coords_to_half_diff_coords`): rotate wi about n by −φh, then about the binormal (+y)
// by −θh; φd is the azimuth of the result. DESIGN.md §2.
#include "brdfkit/core/vec.h"

namespace brdfkit {

struct HalfDiff {
  double theta_h, phi_h, theta_d, phi_d;
};

// Rotation of v about unit axis by angle (Rodrigues), as in MERL's `rotate_vector`.
template <class T> Vec3<T> rotate_about(const Vec3<T>& v, const Vec3<T>& axis, const T& angle) {
  using std::cos;
  using std::sin;
  const T c = cos(angle), s = sin(angle);
  return v * c + axis * (axis.dot(v) * (T(1) - c)) + axis.cross(v) * s;
}

HalfDiff to_half_diff(const Vec3d& wi, const Vec3d& wo);

// Inverse of to_half_diff: wi and wo from (θh, φh, θd, φd).
void from_half_diff(const HalfDiff& hd, Vec3d& wi, Vec3d& wo);

}  // namespace brdfkit
