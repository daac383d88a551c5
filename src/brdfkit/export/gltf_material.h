#pragma once
// glTF 2.0 export of a gltf-metallic-roughness fit (models/gltf_metallic_roughness.h), written and
// read with tinygltf (Debian libtinygltf-dev): one material (pbrMetallicRoughness factors,
// KHR_materials_ior, KHR_materials_specular) on a UV sphere mesh, so the file renders as it is;
// the provenance in asset.extras and material.extras ("brdfkit").
#include <filesystem>

#include "brdfkit/export/provenance.h"
#include "brdfkit/models/model.h"

namespace brdfkit::exporter {

// `brdf` must be of gltf-metallic-roughness (InputError otherwise). Written atomically.
void write_gltf(const std::filesystem::path& file, const Brdf& brdf, const Provenance& p);
// The first material of a glTF file as gltf-metallic-roughness values (factors, and the two
// extensions' values or their defaults); InputError naming the file when it cannot be read.
ParamValues read_gltf_material(const std::filesystem::path& file);

}  // namespace brdfkit::exporter
