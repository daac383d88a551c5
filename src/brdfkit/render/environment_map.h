#pragma once
// Distant lighting from an equirectangular (latitude-longitude) HDR map, with the map convention
// of Mitsuba 3's `envmap` (DESIGN.md §13): world y up; a direction d from the surface towards the
// light reads pixel (u W, v H) with u = atan2(d.x, −d.z)/(2π) wrapped to [0, 1), v = acos(d.y)/π.
// A pixel's radiance holds over its whole solid angle (nearest-pixel look-up), so the sampling
// density of pbrt-v3 §14.2.4 — pixel luminance × sin θ, piecewise constant — is proportional to
// the radiance it samples, up to the sin θ of the row centre.
#include "brdfkit/core/vec.h"
#include "brdfkit/render/image.h"
#include "brdfkit/render/piecewise_constant_2d.h"

namespace brdfkit::render {

class EnvironmentMap {
 public:
  // The same radiance from every direction (the furnace test's light); the renderer samples it by
  // the cosine of the surface it lights (sphere_renderer.h), not through a map.
  static EnvironmentMap constant(const Rgb& radiance);
  // `map` holds linear radiance; it is turned by `rotation_deg` about the world y axis (positive:
  // counter-clockwise seen from above) and multiplied by `intensity`; negative values are set to
  // 0 (and counted). InputError for an empty map or a non-finite value.
  EnvironmentMap(Image map, double rotation_deg, double intensity);

  bool is_constant() const { return constant_; }
  size_t negative_pixels() const { return negative_pixels_; }
  // Whether sample() may be called: a map (not a constant) with some light in it.
  bool samplable() const { return !constant_ && distribution_.valid(); }
  Rgb radiance(const Vec3d& d) const { return lookup(d).radiance; }
  // Radiance and sampling density (per solid angle) of one direction in one map read.
  struct Texel {
    Rgb radiance;
    double pdf;
  };
  Texel lookup(const Vec3d& d) const;
  // A direction with density *pdf per unit solid angle; pdf(d) = p(u, v) / (2π² sin θ).
  Vec3d sample(const Vec2d& u, double* pdf) const;
  double pdf(const Vec3d& d) const { return lookup(d).pdf; }

 private:
  // Radiance and p(u, v) of a pixel packed together in floats: the renderer reads both for each
  // direction its BRDF sampler draws, at random places in a map of megabytes.
  struct Packed {
    float r, g, b, pdf_uv;
  };
  EnvironmentMap() = default;
  Vec2d to_map(const Vec3d& d, double* sin_theta) const;

  bool constant_ = false;
  size_t negative_pixels_ = 0;
  Rgb constant_radiance_ = Rgb::Zero();
  int width_ = 0, height_ = 0;
  std::vector<Packed> texels_;
  double cos_rot_ = 1, sin_rot_ = 0;
  PiecewiseConstant2D distribution_;
};

}  // namespace brdfkit::render
