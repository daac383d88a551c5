#include "brdfkit/export/pbrt_scene.h"

#include <fmt/format.h>

#include "brdfkit/core/atomic_file.h"
#include "brdfkit/core/error.h"
#include "brdfkit/export/scene_files.h"

namespace brdfkit::exporter {
namespace {

std::string conductor(const std::string& name, const std::string& colours, double roughness) {
  return fmt::format("MakeNamedMaterial \"{}\"\n    \"string type\" [ \"conductor\" ]\n{}"
                     "    \"float roughness\" [ {} ]\n    \"bool remaproughness\" [ true ]\n",
                     name, colours, num(roughness));
}
std::string diffuse(const std::string& name, const ParamValues& v, int param) {
  return fmt::format("MakeNamedMaterial \"{}\"\n    \"string type\" [ \"diffuse\" ]\n    \"rgb reflectance\" [ {} ]\n",
                     name, rgb(v.values, param, " "));
}

// The named materials, every parameter under pbrt's own name (models/pbrt_*.h).
std::string materials(const Brdf& brdf) {
  const std::string_view model = brdf.model().name();
  const ParamValues& v = brdf.values();
  const ParamTable& t = brdf.model().params();
  auto shared = [&](const char* name) { return v.values[0][size_t(find_param(t, name))]; };
  auto colour = [&](const char* pbrt_name, const char* param) {
    return fmt::format("    \"rgb {}\" [ {} ]\n", pbrt_name, rgb(v.values, find_param(t, param), " "));
  };
  if (model == "pbrt-conductor")
    return conductor("brdfkit_fit", colour("eta", "eta") + colour("k", "k"), shared("roughness"));
  if (model == "pbrt-conductor-reflectance")
    return conductor("brdfkit_fit", colour("reflectance", "reflectance"), shared("roughness"));
  if (model == "pbrt-diffuse") return diffuse("brdfkit_fit", v, find_param(t, "reflectance"));
  if (model == "pbrt-mix-diffuse-conductor")
    return diffuse("brdfkit_fit_diffuse", v, find_param(t, "reflectance")) +
           conductor("brdfkit_fit_conductor", colour("reflectance", "conductor_reflectance"), shared("roughness")) +
           fmt::format("MakeNamedMaterial \"brdfkit_fit\"\n    \"string type\" [ \"mix\" ]\n"
                       "    \"string materials\" [ \"brdfkit_fit_diffuse\" \"brdfkit_fit_conductor\" ]\n"
                       "    \"float amount\" [ {} ]\n",
                       num(shared("amount")));
  throw InputError("pbrt-v4 export", "needs a pbrt-* fit, got " + std::string(model));
}

std::string scene_text(const std::filesystem::path& material) {
  const Vec3d l = kSceneLight;
  return fmt::format(R"(# brdfkit's point-light sphere: unit sphere at the origin, camera on +z, world y up
LookAt 0 0 {}  0 0 0  0 1 0
Camera "perspective" "float fov" [ {} ]
Film "rgb" "integer xresolution" [ {} ] "integer yresolution" [ {} ] "string filename" [ "sphere.exr" ]
Sampler "independent" "integer pixelsamples" [ 64 ]
Integrator "path" "integer maxdepth" [ 1 ]
WorldBegin
LightSource "distant" "point3 from" [ {} {} {} ] "point3 to" [ 0 0 0 ] "rgb L" [ 1 1 1 ]
Include "{}"
NamedMaterial "brdfkit_fit"
Shape "sphere" "float radius" [ 1 ]
)",
                     num(kSceneCameraZ), num(kSceneFovDeg), kSceneResolution, kSceneResolution, num(l.x()), num(l.y()),
                     num(l.z()), material.filename().string());
}

}  // namespace

std::vector<std::filesystem::path> write_pbrt(const std::filesystem::path& file, const Brdf& brdf, const Provenance& p) {
  const std::string text = comment_block(p, "# ") +
                           "# pbrt-v4 renders spectrally: RGB values are upsampled (exact for grey values only).\n" +
                           materials(brdf);
  const std::filesystem::path scene = scene_path(file);
  write_file_atomically(file, text);
  write_file_atomically(scene, scene_text(file));
  return {file, scene};
}

}  // namespace brdfkit::exporter
