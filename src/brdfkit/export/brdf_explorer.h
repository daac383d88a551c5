#pragma once
// Disney BRDF Explorer `.brdf` export (wdas/brdf, the "analytic" format of its src/brdfs/*.brdf;
// DESIGN.md §14): a `::begin parameters` block declaring every parameter with the fitted value as
// its default (`float name min max value`; `color name r g b` for a per-channel parameter bounded
// in [0, 1], three floats name_r, name_g, name_b otherwise), then a `::begin shader` block with the
// model's GLSL (export/glsl_function.h) and `vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)`.
#include <filesystem>

#include "brdfkit/export/provenance.h"
#include "brdfkit/models/model.h"

namespace brdfkit::exporter {

std::string brdf_explorer_text(const Brdf& brdf, const Provenance& p);
void write_brdf_explorer(const std::filesystem::path& file, const Brdf& brdf, const Provenance& p);

}  // namespace brdfkit::exporter
