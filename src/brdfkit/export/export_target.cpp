#include "brdfkit/export/export_target.h"

#include <algorithm>

#include "brdfkit/core/error.h"
#include "brdfkit/fit/fit_record.h"

namespace brdfkit::exporter {

Target parse_target(const std::string& name, const std::string& option) {
  if (name == "gltf") return Target::Gltf;
  if (name == "mitsuba3") return Target::Mitsuba3;
  if (name == "pbrt-v4") return Target::PbrtV4;
  if (name == "brdf-explorer") return Target::BrdfExplorer;
  if (name == "glsl") return Target::Glsl;
  throw InputError(option + " '" + name + "'", "unknown target; known: gltf, mitsuba3, pbrt-v4, brdf-explorer, glsl");
}

std::string_view target_name(Target t) {
  switch (t) {
    case Target::Gltf: return "gltf";
    case Target::Mitsuba3: return "mitsuba3";
    case Target::PbrtV4: return "pbrt-v4";
    case Target::BrdfExplorer: return "brdf-explorer";
    case Target::Glsl: return "glsl";
  }
  return "";
}

std::vector<std::string> exact_models(Target t) {
  switch (t) {
    case Target::Gltf: return {"gltf-metallic-roughness"};
    case Target::Mitsuba3:
      return {"mitsuba-principled", "mitsuba-roughconductor-beckmann", "mitsuba-roughconductor-ggx"};
    case Target::PbrtV4:
      return {"pbrt-mix-diffuse-conductor", "pbrt-conductor", "pbrt-conductor-reflectance", "pbrt-diffuse"};
    default: return {};
  }
}

const Model& default_model(Target t) {
  const auto models = exact_models(t);
  if (models.empty()) throw InputError("--to " + std::string(target_name(t)), "writes every model: nothing to refit into");
  return model_by_name(models.front());
}

bool exports_exactly(Target t, const Model& model, const ParamValues& values) {
  const auto models = exact_models(t);
  if (models.empty()) return true;
  return std::find(models.begin(), models.end(), std::string(model.name())) != models.end() &&
         !fit::shape_differs_by_channel(model, values);
}

}  // namespace brdfkit::exporter
