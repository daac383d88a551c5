#pragma once
// Square-to-sphere warps used by importance sampling, with their densities.
#include "brdfkit/core/vec.h"

namespace brdfkit {

// Cosine-weighted hemisphere (Malley's method through the concentric disk), pdf = cosθ/π.
inline Vec3d square_to_cosine_hemisphere(const Vec2d& u) {
  const double a = 2 * u.x() - 1, b = 2 * u.y() - 1;
  double r = 0, phi = 0;
  if (a != 0 || b != 0) {
    if (a * a > b * b) {
      r = a;
      phi = (kPi / 4) * (b / a);
    } else {
      r = b;
      phi = (kPi / 2) - (kPi / 4) * (a / b);
    }
  }
  const double x = r * std::cos(phi), y = r * std::sin(phi);
  return Vec3d(x, y, std::sqrt(std::max(0.0, 1 - x * x - y * y)));
}
inline double cosine_hemisphere_pdf(const Vec3d& w) { return w.z() > 0 ? w.z() * kInvPi : 0.0; }

// Orthonormal frame around a unit vector n (Duff et al. 2017), columns = (s, t, n).
inline Eigen::Matrix3d frame_around(const Vec3d& n) {
  const double sign = std::copysign(1.0, n.z());
  const double a = -1.0 / (sign + n.z()), b = n.x() * n.y() * a;
  Eigen::Matrix3d m;
  m.col(0) = Vec3d(1 + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
  m.col(1) = Vec3d(b, sign + n.y() * n.y() * a, -n.y());
  m.col(2) = n;
  return m;
}

}  // namespace brdfkit
