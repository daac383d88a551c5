#include "brdfkit/render/color.h"

#include <cmath>

namespace brdfkit::render {

Vec3d linear_srgb_to_xyz(const Rgb& c) {
  // IEC 61966-2-1:1999 Eq. 7 (the inverse of its Eq. 6 matrix, 4 decimals as printed).
  return Vec3d(0.4124 * c[0] + 0.3576 * c[1] + 0.1805 * c[2],  //
               0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2],  //
               0.0193 * c[0] + 0.1192 * c[1] + 0.9505 * c[2]);
}

Vec3d d65_white() { return linear_srgb_to_xyz(Rgb(1, 1, 1)); }

Lab xyz_to_lab(const Vec3d& xyz, const Vec3d& white) {
  // CIE 15:2004 Eqs. 8.3–8.5: f(t) = t^(1/3) above (6/29)³, linear below.
  constexpr double e = 216.0 / 24389.0, k = 24389.0 / 27.0;
  auto f = [&](double t) { return t > e ? std::cbrt(t) : (k * t + 16) / 116; };
  const double fx = f(xyz.x() / white.x()), fy = f(xyz.y() / white.y()), fz = f(xyz.z() / white.z());
  return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

Lab linear_srgb_to_lab(const Rgb& rgb, double white_y) { return xyz_to_lab(linear_srgb_to_xyz(rgb), d65_white() * white_y); }

double srgb_encode(double v) {
  // IEC 61966-2-1:1999 Eq. 5 (inverse of the decoding of its §5.2).
  if (!(v > 0)) return 0;
  if (v >= 1) return 1;
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
}

}  // namespace brdfkit::render
