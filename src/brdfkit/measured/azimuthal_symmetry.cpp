#include "brdfkit/measured/azimuthal_symmetry.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace brdfkit {

namespace {

using Map = std::function<Vec3d(const Vec3d&)>;

Map rotation(double angle) {
  return [c = std::cos(angle), s = std::sin(angle)](const Vec3d& v) {
    return Vec3d(c * v.x() - s * v.y(), s * v.x() + c * v.y(), v.z());
  };
}

bool same(const std::optional<Rgb>& a, const std::optional<Rgb>& b) {
  if (!a || !b) return !a && !b;
  const double scale = std::max(a->cwiseAbs().maxCoeff(), b->cwiseAbs().maxCoeff());
  return ((*a - *b).cwiseAbs().maxCoeff() <= 1e-6 * scale + 1e-12);
}

// Whether ρ is unchanged by every map in `maps` at every probe pair.
bool invariant(const RglSource& rho, const std::vector<Map>& maps) {
  const double deg = kPi / 180;
  for (double ti : {20.0, 55.0})
    for (double pi : {17.0, 133.0})
      for (double to : {35.0, 62.0})
        for (double dp : {41.0, 163.0}) {
          const Vec3d wi = spherical_direction(ti * deg, pi * deg), wo = spherical_direction(to * deg, (pi + dp) * deg);
          const std::optional<Rgb> v = rho(wi, wo);
          for (const Map& r : maps)
            if (!same(v, rho(r(wi), r(wo)))) return false;
        }
  return true;
}

}  // namespace

AzimuthalSymmetry azimuthal_symmetry(const RglSource& rho) {
  const double deg = kPi / 180;
  if (invariant(rho, {rotation(37 * deg), rotation(90 * deg), rotation(211 * deg)})) return AzimuthalSymmetry::Isotropic;
  if (!invariant(rho, {rotation(kPi)})) return AzimuthalSymmetry::None;
  const Map mirror_x = [](const Vec3d& v) { return Vec3d(-v.x(), v.y(), v.z()); };
  const Map mirror_y = [](const Vec3d& v) { return Vec3d(v.x(), -v.y(), v.z()); };
  return invariant(rho, {mirror_x, mirror_y}) ? AzimuthalSymmetry::Mirrors : AzimuthalSymmetry::HalfTurn;
}

int rgl_symmetry(AzimuthalSymmetry s) {
  switch (s) {
    case AzimuthalSymmetry::None: return 1;
    case AzimuthalSymmetry::HalfTurn: return 2;
    default: return 4;
  }
}

}  // namespace brdfkit
