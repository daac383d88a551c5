#pragma once
// Scenes and settings shared by the render tests: a synthetic environment map (no data needed)
// and small, fast render settings.
#include "brdfkit/render/environment_map.h"
#include "brdfkit/render/scene.h"
#include "brdfkit/render/sphere_renderer.h"

namespace brdfkit::test {
using namespace brdfkit::render;

// A 64 × 32 map: a sky brightening towards the zenith, a dim ground, and a small bright "sun"
// (radiance 60) 40° above the horizon, so environment sampling matters.
inline Image synthetic_sky() {
  Image img(64, 32);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const double v = (y + 0.5) / img.height;  // 0 at the zenith
      Rgb c = v < 0.5 ? Rgb(0.3, 0.5, 1.0) * (1.2 - v) : Rgb(0.2, 0.15, 0.1);
      if (std::abs(x - 20) <= 1 && std::abs(y - 7) <= 1) c = Rgb(60, 55, 45);
      img.at(x, y) = c;
      img.covered[size_t(y) * 64 + size_t(x)] = 1;
    }
  return img;
}

inline Scene sky_scene() {
  Scene s;
  s.environment = EnvironmentMap(synthetic_sky(), 0, 1);
  return s;
}

inline RenderSettings small_settings(int size, int spp, std::uint64_t seed = 1) {
  RenderSettings s;
  s.width = s.height = size;
  s.spp = spp;
  s.seed = seed;
  return s;
}

}  // namespace brdfkit::test
