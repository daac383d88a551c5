#include "brdfkit/render/camera.h"

#include <cmath>

#include "brdfkit/core/error.h"

namespace brdfkit::render {

Camera::Camera(int width, int height, double distance, double margin)
    : width_(width), height_(height), distance_(distance) {
  if (width < 1 || height < 1) throw InputError("image size", "width and height must be at least 1");
  if (!(distance > 1)) throw InputError("camera distance", "must be > 1 (outside the unit sphere)");
  tan_half_fov_ = std::tan(std::asin(1 / distance) * margin);
}

std::optional<SphereHit> Camera::hit(double px, double py) const {
  const double aspect = double(width_) / height_;
  const Vec3d dir =
      Vec3d((2 * px / width_ - 1) * tan_half_fov_ * aspect, (1 - 2 * py / height_) * tan_half_fov_, -1).normalized();
  const Vec3d origin(0, 0, distance_);
  // |o + t d|² = 1 → t² + 2 (o·d) t + |o|² − 1 = 0; the nearer root.
  const double b = origin.dot(dir), c = origin.squaredNorm() - 1, disc = b * b - c;
  if (disc <= 0) return std::nullopt;
  const Vec3d n = (origin + (-b - std::sqrt(disc)) * dir).normalized();
  Vec3d t = Vec3d::UnitY().cross(n);
  // At the poles (n = ±y, never inside the image) any tangent will do.
  t = t.squaredNorm() > 1e-24 ? t.normalized() : Vec3d::UnitX();
  SphereHit h;
  h.to_local.row(0) = t.transpose();
  h.to_local.row(1) = n.cross(t).transpose();
  h.to_local.row(2) = n.transpose();
  h.wo_local = h.to_local * (-dir);
  if (h.wo_local.z() <= 0) return std::nullopt;  // the silhouette itself
  return h;
}

}  // namespace brdfkit::render
