#pragma once
// Mitsuba 3 export (XML scene format of Mitsuba 3 v3.9.1): the material file — a <scene> holding
// one <bsdf id="brdfkit_fit"> of type principled or roughconductor with the fitted values — and
// beside it "<stem>_scene.xml", which <include>s it and renders a unit sphere under one
// directional light with the `direct` integrator (DESIGN.md §13's setup). RGB values: render with
// an RGB variant (scalar_rgb, llvm_ad_rgb) to reproduce ρ per channel.
#include <filesystem>
#include <vector>

#include "brdfkit/export/provenance.h"
#include "brdfkit/models/model.h"

namespace brdfkit::exporter {

// `brdf` of mitsuba-principled or mitsuba-roughconductor-{beckmann,ggx}; InputError otherwise.
// Returns the files written (material, scene), each atomically.
std::vector<std::filesystem::path> write_mitsuba(const std::filesystem::path& file, const Brdf& brdf, const Provenance& p);

}  // namespace brdfkit::exporter
