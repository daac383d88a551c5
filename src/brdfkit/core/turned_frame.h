#pragma once
// The local frame turned by φ about the normal: x' along (cos φ, sin φ, 0), the tangent of an
// oriented lobe (phi_t of the anisotropic models), y' along (−sin φ, cos φ, 0), z' = z.
#include <cmath>

#include "brdfkit/core/vec.h"

namespace brdfkit {

template <class T> struct TurnedFrame {
  T c, s;
  explicit TurnedFrame(const T& phi) {
    using std::cos;
    using std::sin;
    c = cos(phi);
    s = sin(phi);
  }
  Vec3<T> to_local(const Vec3<T>& v) const { return Vec3<T>(c * v.x() + s * v.y(), -s * v.x() + c * v.y(), v.z()); }
  Vec3<T> to_world(const Vec3<T>& v) const { return Vec3<T>(c * v.x() - s * v.y(), s * v.x() + c * v.y(), v.z()); }
};

}  // namespace brdfkit
