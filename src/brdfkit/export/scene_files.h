#pragma once
// What the Mitsuba 3 and pbrt-v4 exporters share: the minimal scene's geometry (DESIGN.md §13:
// a unit sphere at the origin seen from +z, world y up, one distant light) and number formatting.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "brdfkit/core/vec.h"
#include "brdfkit/export/provenance.h"

namespace brdfkit::exporter {

// The light's direction (towards the light) and the camera of the minimal scenes.
inline const Vec3d kSceneLight = Vec3d(0.5, 0.5, 0.70710678118654752);
inline constexpr double kSceneCameraZ = 4.0;
inline constexpr double kSceneFovDeg = 35.0;
inline constexpr int kSceneResolution = 256;

// Round-trip decimal (17 significant digits).
std::string num(double x);
// "r, g, b" (Mitsuba) or "r g b" (pbrt) of a per-channel parameter.
std::string rgb(const std::array<std::vector<double>, 3>& channels, int param, const char* sep);
// The provenance as comment lines with `prefix` ("# " for pbrt, "  " inside an XML comment).
std::string comment_block(const Provenance& p, const std::string& prefix);
// "<dir>/<stem>_scene<ext>" beside the material file.
std::filesystem::path scene_path(const std::filesystem::path& material_file);

}  // namespace brdfkit::exporter
