#pragma once
// pbrt-v4 export (scene description of mmp/pbrt-v4, commit 5f7a6068): the material file — named
// materials ("brdfkit_fit"; a mix also names its two parts) with the fitted values — and beside it
// "<stem>_scene.pbrt", which Includes it and renders a unit sphere under one distant light with
// the `path` integrator at maxdepth 1 (direct light only; DESIGN.md §13's setup). pbrt-v4 renders
// spectrally: RGB values are upsampled, exact for grey eta, k and reflectance only.
#include <filesystem>
#include <vector>

#include "brdfkit/export/provenance.h"
#include "brdfkit/models/model.h"

namespace brdfkit::exporter {

// `brdf` of pbrt-conductor, pbrt-conductor-reflectance, pbrt-diffuse or pbrt-mix-diffuse-conductor;
// InputError otherwise. Returns the files written (material, scene), each atomically.
std::vector<std::filesystem::path> write_pbrt(const std::filesystem::path& file, const Brdf& brdf, const Provenance& p);

}  // namespace brdfkit::exporter
