#include "brdfkit/measured/write_measured.h"

#include <fmt/format.h>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/merl.h"
#include "brdfkit/measured/merl_tabulate.h"

namespace brdfkit {

RglWriteOptions rgl_layout(const MeasuredWriteRequest& r, AzimuthalSymmetry found, const Warn& warn) {
  RglWriteOptions opt;
  opt.theta_i = r.theta_i;
  opt.description = r.description;
  const int found_symmetry = rgl_symmetry(found);
  opt.symmetry = r.symmetry ? r.symmetry : found_symmetry;
  opt.phi_i = r.phi_i ? r.phi_i : found == AzimuthalSymmetry::Isotropic ? 1 : 24 / opt.symmetry + 1;
  opt.grid = r.grid ? r.grid : opt.phi_i == 1 ? 64 : 32;
  if (opt.phi_i == 1 && found != AzimuthalSymmetry::Isotropic)
    warn("the source is anisotropic; an isotropic file (one phi_i node) keeps its values at φi = 0 only");
  if (opt.phi_i > 1 && opt.symmetry > found_symmetry)
    warn(fmt::format("symmetry {}: the source does not have it (probed: {}); the file shows it as if it had", opt.symmetry,
                     found_symmetry));
  return opt;
}

std::string write_measured(const std::filesystem::path& file, const RglSource& rho, const MeasuredWriteRequest& request,
                           const Warn& warn) {
  const std::string ext = file.extension().string();
  if (ext != ".binary" && ext != ".bsdf")
    throw InputError(file.string(), "the output format comes from the extension: .binary (MERL) or .bsdf (RGL)");
  const AzimuthalSymmetry found = azimuthal_symmetry(rho);
  if (ext == ".binary") {
    if (found != AzimuthalSymmetry::Isotropic) warn(kMerlDropsAnisotropy);
    // −1 is MERL's "not measured".
    merl::write(file, merl::tabulate([&](const Vec3d& wi, const Vec3d& wo) { return rho(wi, wo).value_or(Rgb::Constant(-1)); }));
    return "MERL";
  }
  const RglWriteOptions opt = rgl_layout(request, found, warn);
  write_rgl(file, rho, opt);
  if (opt.phi_i == 1) return "isotropic RGL tensor_file";
  return fmt::format("anisotropic RGL tensor_file ({} phi_i nodes over 1/{} of the azimuths)", opt.phi_i, opt.symmetry);
}

}  // namespace brdfkit
