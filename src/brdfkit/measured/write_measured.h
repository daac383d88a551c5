#pragma once
// Writes any BRDF given as a function in the measured format its file name asks for: `.binary`
// as a MERL table (measured/merl_tabulate.h; where the function has no value the cell is written
// as not measured), `.bsdf` as an RGL tensor_file (measured/rgl_writer.h). Atomic, both.
#include <filesystem>

#include "brdfkit/measured/rgl_writer.h"

namespace brdfkit {

// InputError naming the file when its extension is neither .binary nor .bsdf.
void write_measured(const std::filesystem::path& file, const RglSource& rho, const RglWriteOptions& rgl = {});

}  // namespace brdfkit
