#pragma once
// The sphere of camera.h shaded by a Reflector under a Scene. Per pixel radiance
// L(wo) = ∫ L_env(wi) ρ(wi, wo) cos θi dωi + Σ_lights I ρ(l, wo) cos θl (DESIGN.md §13).
// Estimator (Veach 1997 §9.2, pbrt-v3 §14.3.1): each sample draws one direction from the
// environment map's distribution (for a constant environment: the cosine-weighted hemisphere,
// which samples L cos θi exactly) and one from the reflector's sampler, and weights both by the
// power heuristic (β = 2). A Lambertian surface, whose sampler is the cosine too, then gets ρ from
// every sample. Point lights are added exactly. Every pixel has its own random stream seeded from (seed, pixel), so the image
// does not depend on the thread count or the schedule.
#include <cstdint>
#include <functional>

#include "brdfkit/render/camera.h"
#include "brdfkit/render/image.h"
#include "brdfkit/render/reflector.h"
#include "brdfkit/render/scene.h"

namespace brdfkit::render {

struct RenderSettings {
  int width = 256, height = 256;
  int spp = 64;                 // samples per pixel (each: one environment + one BRDF draw)
  std::uint64_t seed = 1;
  bool jitter = true;           // false: every sample through the pixel centre (tests)
  double camera_distance = 4;
  std::function<void(double)> progress;  // fraction done, called at most every 5 %
};

struct RenderResult {
  Image radiance;            // linear RGB
  Image standard_error;      // per pixel and channel: sample standard deviation / √spp
  std::size_t dropped = 0;   // samples whose value was NaN or infinite (left out)
};

// Multi-threaded (TBB over rows); InputError for a non-positive size or sample count.
RenderResult render_sphere(const Reflector& reflector, const Scene& scene, const RenderSettings& settings);

}  // namespace brdfkit::render
