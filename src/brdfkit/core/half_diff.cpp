#include "brdfkit/core/half_diff.h"

#include <algorithm>

namespace brdfkit {

HalfDiff to_half_diff(const Vec3d& wi, const Vec3d& wo) {
  const Vec3d h = (wi + wo).normalized();
  HalfDiff hd;
  hd.theta_h = std::acos(std::clamp(h.z(), -1.0, 1.0));
  hd.phi_h = std::atan2(h.y(), h.x());
  const Vec3d tmp = rotate_about<double>(wi, Vec3d::UnitZ(), -hd.phi_h);
  const Vec3d diff = rotate_about<double>(tmp, Vec3d::UnitY(), -hd.theta_h);
  hd.theta_d = std::acos(std::clamp(diff.z(), -1.0, 1.0));
  hd.phi_d = std::atan2(diff.y(), diff.x());
  return hd;
}

void from_half_diff(const HalfDiff& hd, Vec3d& wi, Vec3d& wo) {
  const Vec3d h = spherical_direction(hd.theta_h, hd.phi_h);
  const Vec3d d = spherical_direction(hd.theta_d, hd.phi_d);
  wi = rotate_about<double>(rotate_about<double>(d, Vec3d::UnitY(), hd.theta_h), Vec3d::UnitZ(), hd.phi_h);
  wo = reflect<double>(wi, h);
}

}  // namespace brdfkit
