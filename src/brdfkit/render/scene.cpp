#include "brdfkit/render/scene.h"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include "brdfkit/core/error.h"
#include "brdfkit/core/text.h"
#include "brdfkit/render/image_io.h"

namespace brdfkit::render {

PointLight light_from_camera_angles(double theta_deg, double phi_deg, const Rgb& intensity) {
  const double t = theta_deg * kPi / 180, p = phi_deg * kPi / 180;
  return {Vec3d(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)), intensity};
}

PointLight parse_light(const std::string& arg) {
  const std::string where = "--light '" + arg + "'";
  std::vector<double> v;
  std::stringstream ss(arg);
  for (std::string part; std::getline(ss, part, ',');) {
    const std::optional<double> x = finite_number(part);
    if (!x) throw InputError(where, "'" + part + "' is not a finite number");
    v.push_back(*x);
  }
  if (v.size() != 2 && v.size() != 3 && v.size() != 5) throw InputError(where, "expected theta,phi[,intensity] or theta,phi,r,g,b (degrees)");
  Rgb i = v.size() == 5 ? Rgb(v[2], v[3], v[4]) : Rgb::Constant(v.size() == 3 ? v[2] : 1.0);
  if ((i < 0).any()) throw InputError(where, "intensity must be >= 0");
  return light_from_camera_angles(v[0], v[1], i);
}

Scene builtin_scene() {
  Scene s;
  s.environment = EnvironmentMap::constant(Rgb::Constant(0.1));
  s.lights = {light_from_camera_angles(45, 135, Rgb::Constant(3.0)), light_from_camera_angles(60, -20, Rgb::Constant(0.8))};
  s.description = "built-in: key light (45 deg, upper left, 3), fill light (60 deg, right, 0.8), uniform sky 0.1";
  return s;
}

Scene make_scene(const SceneSettings& a) {
  if (a.env.empty() && !a.env_constant && a.lights.empty()) return builtin_scene();
  Scene s;
  if (!a.env.empty()) {
    if (!std::isfinite(a.env_rotation)) throw SettingError("env_rotation", "must be a finite angle in degrees");
    if (!(a.env_intensity >= 0) || !std::isfinite(a.env_intensity)) throw SettingError("env_intensity", "must be >= 0");
    s.environment = EnvironmentMap(read_hdr_image(a.env), a.env_rotation, a.env_intensity);
    s.description = fmt::format("environment {} (rotated {} deg, x{})", a.env, a.env_rotation, a.env_intensity);
  } else if (a.env_constant) {
    if (!(*a.env_constant >= 0) || !std::isfinite(*a.env_constant))
      throw SettingError("env_constant", "radiance must be >= 0");
    s.environment = EnvironmentMap::constant(Rgb::Constant(*a.env_constant));
    s.description = fmt::format("constant environment {}", *a.env_constant);
  }
  for (const std::string& l : a.lights) {
    s.lights.push_back(parse_light(l));
    s.description += (s.description.empty() ? "" : " + ") + std::string("light ") + l;
  }
  return s;
}

}  // namespace brdfkit::render
