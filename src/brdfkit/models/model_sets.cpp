#include "brdfkit/models/model_sets.h"

#include <algorithm>
#include <sstream>
#include <string_view>

#include "brdfkit/core/error.h"

namespace brdfkit {

int lobe_count(const Model& model) {
  int scales = 0;
  bool shape = false;
  for (const ParamSpec& s : model.params()) {
    if (s.scope == Scope::PerChannel && s.linear && s.name != "kd") ++scales;
    if (s.scope == Scope::Shared) shape = true;
  }
  return scales > 0 ? scales : (shape ? 1 : 0);
}

bool is_renderer_model(const Model& model) {
  for (std::string_view prefix : {"gltf-", "mitsuba-", "pbrt-", "disney-"})
    if (model.name().starts_with(prefix)) return true;
  return false;
}

bool is_oriented(const Model& model) { return find_param(model.params(), "phi_t") >= 0; }

std::vector<const Model*> parse_model_set(const std::string& spec) {
  std::vector<const Model*> out;
  if (spec == "all") {
    for (const Model* m : all_models()) out.push_back(m);
    return out;
  }
  if (spec == "single-lobe") {
    for (const Model* m : all_models())
      if (lobe_count(*m) == 1 && !is_renderer_model(*m) && !is_oriented(*m)) out.push_back(m);
    return out;
  }
  if (spec == "anisotropic") {
    for (const Model* m : all_models())
      if (is_oriented(*m) || m->name() == "ward-aniso") out.push_back(m);
    return out;
  }
  if (spec == "renderer") {
    for (const Model* m : all_models())
      if (is_renderer_model(*m)) out.push_back(m);
    return out;
  }
  std::stringstream ss(spec);
  std::string name;
  while (std::getline(ss, name, ',')) {
    if (name.empty()) continue;
    const Model* m = &model_by_name(name);  // InputError listing the known names
    if (std::find(out.begin(), out.end(), m) == out.end()) out.push_back(m);
  }
  if (out.empty()) throw SettingError("models", "no model named (give names, 'all', 'single-lobe', 'renderer' or 'anisotropic')");
  return out;
}

}  // namespace brdfkit
