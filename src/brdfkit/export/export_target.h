#pragma once
// The formats `brdfkit export --to` writes and, for the renderers, the catalogue models each one
// reproduces exactly (DESIGN.md §14): a fit in one of them is written as it is; a fit of any other
// model is refitted into the format's default model first (export/refit.h).
#include <string>
#include <string_view>
#include <vector>

#include "brdfkit/models/model.h"

namespace brdfkit::exporter {

enum class Target { Gltf, Mitsuba3, PbrtV4, BrdfExplorer, Glsl };

// "gltf", "mitsuba3", "pbrt-v4", "brdf-explorer", "glsl"; InputError naming `option` otherwise.
Target parse_target(const std::string& name, const std::string& option = "--to");
std::string_view target_name(Target t);

// The models the target writes exactly (empty for brdf-explorer and glsl: every model, as GLSL).
std::vector<std::string> exact_models(Target t);
// The model a fit of another model is refitted into (glTF: gltf-metallic-roughness; Mitsuba 3:
// mitsuba-principled; pbrt-v4: pbrt-mix-diffuse-conductor, its only closed-form diffuse + glossy).
const Model& default_model(Target t);
// Whether a fit of `model` with these values is written exactly: its model is one of the target's
// and, for the renderers, its lobe shape is one for R, G and B (a renderer takes one roughness).
bool exports_exactly(Target t, const Model& model, const ParamValues& values);

}  // namespace brdfkit::exporter
