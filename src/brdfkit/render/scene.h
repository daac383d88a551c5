#pragma once
// The light around the sphere: an environment (a map or a constant) and distant point lights.
#include <optional>
#include <string>
#include <vector>

#include "brdfkit/core/vec.h"
#include "brdfkit/render/environment_map.h"

namespace brdfkit::render {

// A distant light: direction towards it (world frame, unit) and intensity I, so that it adds
// I ρ(l, wo) cos θl to a pixel (DESIGN.md §13), no Monte Carlo involved.
struct PointLight {
  Vec3d direction;
  Rgb intensity;
};

// θ from the camera axis (+z, towards the viewer), φ counter-clockwise in the image plane from its
// right-hand side (+x; 90° is up), both in degrees.
PointLight light_from_camera_angles(double theta_deg, double phi_deg, const Rgb& intensity);
// "θ,φ[,I]" or "θ,φ,R,G,B" (degrees; I defaults to 1): InputError naming the argument otherwise.
PointLight parse_light(const std::string& arg);

struct Scene {
  std::optional<EnvironmentMap> environment;
  std::vector<PointLight> lights;
  std::string description;  // how it was made, for the output's metadata
};

// The light used when none is given: a key light 45° from the camera towards the upper left
// (φ = 135°) of intensity 3, a fill light 60° towards the right (φ = −20°) of intensity 0.8, and a
// uniform environment of radiance 0.1 (so the rim never goes black).
Scene builtin_scene();

// The light a caller describes: a map (path, turned about the vertical axis by `env_rotation`
// degrees, radiance × `env_intensity`) or a constant environment, and lights in parse_light's
// form. Nothing at all: builtin_scene(). InputError naming the map file, a light or the setting.
struct SceneSettings {
  std::string env;
  double env_rotation = 0, env_intensity = 1;
  std::optional<double> env_constant;
  std::vector<std::string> lights;
};
Scene make_scene(const SceneSettings& s);

}  // namespace brdfkit::render
