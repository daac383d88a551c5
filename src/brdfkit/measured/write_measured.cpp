#include "brdfkit/measured/write_measured.h"

#include <fmt/format.h>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/merl.h"
#include "brdfkit/measured/merl_tabulate.h"

namespace brdfkit {

void write_measured(const std::filesystem::path& file, const RglSource& rho, const RglWriteOptions& rgl) {
  const std::string ext = file.extension().string();
  if (ext == ".binary") {
    // −1 is MERL's "not measured".
    merl::write(file, merl::tabulate([&](const Vec3d& wi, const Vec3d& wo) { return rho(wi, wo).value_or(Rgb::Constant(-1)); }));
  } else if (ext == ".bsdf") {
    write_rgl(file, rho, rgl);
  } else {
    throw InputError(file.string(), "the output format comes from the extension: .binary (MERL) or .bsdf (RGL)");
  }
}

}  // namespace brdfkit
