#include "brdfkit/render/environment_map.h"

#include <cmath>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/summary.h"

namespace brdfkit::render {

EnvironmentMap EnvironmentMap::constant(const Rgb& radiance) {
  EnvironmentMap e;
  e.constant_ = true;
  e.constant_radiance_ = radiance;
  return e;
}

EnvironmentMap::EnvironmentMap(Image map, double rotation_deg, double intensity)
    : width_(map.width), height_(map.height), texels_(map.size()) {
  if (map.width < 2 || map.height < 1) throw InputError("environment map", "empty image");
  if (!std::isfinite(intensity) || intensity < 0) throw InputError("environment intensity", "must be finite and >= 0");
  std::vector<double> weights(map.size());
  for (int y = 0; y < map.height; ++y) {
    const double sin_theta = std::sin(kPi * (y + 0.5) / map.height);
    for (int x = 0; x < map.width; ++x) {
      Rgb& v = map.at(x, y);
      if (!v.allFinite())
        throw InputError("environment map", "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is not finite");
      // Lossy EXR compression (DWAB, as in ../shared/data/envmaps) leaves small negative values
      // near dark edges; radiance cannot be negative.
      negative_pixels_ += (v < 0).any();
      v = v.cwiseMax(0.0) * intensity;
      weights[size_t(y) * size_t(map.width) + size_t(x)] = luminance(v) * sin_theta;
    }
  }
  distribution_ = PiecewiseConstant2D(weights, map.width, map.height);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      const Rgb& v = map.at(x, y);
      const Vec2d centre((x + 0.5) / map.width, (y + 0.5) / map.height);
      texels_[size_t(y) * size_t(map.width) + size_t(x)] = {float(v[0]), float(v[1]), float(v[2]), float(distribution_.pdf(centre))};
    }
  cos_rot_ = std::cos(rotation_deg * kPi / 180);
  sin_rot_ = std::sin(rotation_deg * kPi / 180);
}

Vec2d EnvironmentMap::to_map(const Vec3d& d, double* sin_theta) const {
  // Undo the rotation about y, then DESIGN.md §13's (u, v).
  const Vec3d m(cos_rot_ * d.x() - sin_rot_ * d.z(), d.y(), sin_rot_ * d.x() + cos_rot_ * d.z());
  double u = std::atan2(m.x(), -m.z()) / (2 * kPi);
  if (u < 0) u += 1;
  const double cos_t = std::clamp(m.y(), -1.0, 1.0);
  *sin_theta = std::sqrt(std::max(0.0, 1 - cos_t * cos_t));
  return Vec2d(std::min(u, 1.0 - 1e-12), std::acos(cos_t) / kPi);
}

EnvironmentMap::Texel EnvironmentMap::lookup(const Vec3d& d) const {
  if (constant_) return {constant_radiance_, 0.0};
  double sin_theta = 0;
  const Vec2d uv = to_map(d, &sin_theta);
  const int x = std::min(int(uv.x() * width_), width_ - 1), y = std::min(int(uv.y() * height_), height_ - 1);
  const Packed& t = texels_[size_t(y) * size_t(width_) + size_t(x)];
  const double pdf = sin_theta > 0 && distribution_.valid() ? t.pdf_uv / (2 * kPi * kPi * sin_theta) : 0;
  return {Rgb(t.r, t.g, t.b), pdf};
}

Vec3d EnvironmentMap::sample(const Vec2d& u, double* pdf) const {
  double p_uv = 0;
  const Vec2d uv = distribution_.sample(u, &p_uv);
  const double phi = 2 * kPi * uv.x(), theta = kPi * uv.y();
  const double sin_t = std::sin(theta);
  // Inverse of to_map: m = (sin θ sin φ, cos θ, −sin θ cos φ), then the rotation about y.
  const Vec3d m(sin_t * std::sin(phi), std::cos(theta), -sin_t * std::cos(phi));
  *pdf = sin_t > 0 ? p_uv / (2 * kPi * kPi * sin_t) : 0;
  return Vec3d(cos_rot_ * m.x() + sin_rot_ * m.z(), m.y(), -sin_rot_ * m.x() + cos_rot_ * m.z());
}

}  // namespace brdfkit::render
