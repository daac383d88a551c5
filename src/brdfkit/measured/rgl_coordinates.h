#pragma once
// The angle ↔ unit-square coordinates of RGL tables (Mitsuba 3 `measured`, Dupuy & Jakob 2018 §5):
// θ ↦ u = sqrt(2θ/π) (finer near the normal), φ ↦ (φ + π)/2π; shared by the reader and the writer.
#include <algorithm>
#include <cmath>

#include "brdfkit/core/vec.h"

namespace brdfkit::rgl {

inline double theta2u(double theta) { return std::sqrt(theta * (2 / kPi)); }
inline double phi2u(double phi) { return (phi + kPi) * (0.5 / kPi); }
inline double u2theta(double u) { return u * u * (kPi / 2); }
inline double u2phi(double u) { return (2 * u - 1) * kPi; }
// Polar angle, accurate near the normal (acos(z) loses half the digits there).
inline double elevation(const Vec3d& d) {
  const double dist = std::sqrt(d.x() * d.x() + d.y() * d.y() + (d.z() - 1) * (d.z() - 1));
  return 2 * std::asin(std::min(1.0, 0.5 * dist));
}
// |dωm/du| of the half vector's unit-square coordinates: dωm = sinθm dθm dφm, dθm = π u du,
// dφm = 2π dv (Mitsuba 3 `measured`: the 2π² u sinθm of its Jacobian).
inline double half_vector_jacobian(double u_theta) { return 2 * kPi * kPi * u_theta * std::sin(u2theta(u_theta)); }

}  // namespace brdfkit::rgl
