#pragma once
// The scene of DESIGN.md §13: a unit sphere at the origin of a y-up world, seen by a pinhole camera
// on the +z axis looking at it. At a hit point the local frame of §2 has n = the hit point and
// tangent = normalize(y × n); every direction of n's upper hemisphere leaves the (convex) sphere,
// so nothing is occluded.
#include <optional>

#include "brdfkit/core/vec.h"

namespace brdfkit::render {

struct SphereHit {
  Eigen::Matrix3d to_local;  // rows: tangent, bitangent = n × tangent, n
  Vec3d wo_local;            // towards the camera, in the local frame
  Vec3d to_world(const Vec3d& local) const { return to_local.transpose() * local; }
  Vec3d to_local_dir(const Vec3d& world) const { return to_local * world; }
};

class Camera {
 public:
  // `distance` from the sphere's centre; the vertical field of view is the sphere's angular
  // diameter times `margin`, so the sphere fills the frame with a thin border.
  Camera(int width, int height, double distance = 4.0, double margin = 1.06);
  // The ray through image point (px, py), in pixels from the top-left corner (pixel (x, y) spans
  // [x, x+1) × [y, y+1)); nullopt when it misses the sphere.
  std::optional<SphereHit> hit(double px, double py) const;

 private:
  int width_, height_;
  double distance_, tan_half_fov_;
};

}  // namespace brdfkit::render
