#pragma once
// Writes any BRDF given as a function in the measured format its file name asks for: `.binary`
// as a MERL table (measured/merl_tabulate.h; where the function has no value the cell is written
// as not measured), `.bsdf` as an RGL tensor_file (measured/rgl_writer.h), isotropic or
// anisotropic as the source is unless told. Atomic, both.
#include <filesystem>
#include <functional>
#include <string>

#include "brdfkit/measured/azimuthal_symmetry.h"
#include "brdfkit/measured/rgl_writer.h"

namespace brdfkit {

// What the user asks of the file; 0 leaves the choice to the source (rgl_layout).
struct MeasuredWriteRequest {
  int theta_i = 16, phi_i = 0, symmetry = 0, grid = 0;
  std::string description;
};

using Warn = std::function<void(const std::string&)>;

// The RGL layout for a source of symmetry `found`: isotropic or anisotropic as probed (24 azimuth
// steps around the circle, over the share of it the symmetry lets the file store), a 64² colour
// grid per node, 32² for the many nodes of an anisotropic file; what the request gives wins.
// Warns when the layout drops the source's anisotropy or relies on a symmetry it lacks.
RglWriteOptions rgl_layout(const MeasuredWriteRequest& request, AzimuthalSymmetry found, const Warn& warn);

// Writes the file; returns what was written ("MERL", "isotropic RGL tensor_file", ...). InputError
// naming the file when its extension is neither .binary nor .bsdf.
std::string write_measured(const std::filesystem::path& file, const RglSource& rho, const MeasuredWriteRequest& request,
                           const Warn& warn);

// The warning for writing an anisotropic source as a MERL table (isotropic by its layout).
inline constexpr const char* kMerlDropsAnisotropy =
    "the source is anisotropic; a MERL table is isotropic and keeps its values at φh = 0 only";

}  // namespace brdfkit
