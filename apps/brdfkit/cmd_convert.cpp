// `brdfkit convert SOURCE -o OUT.binary|OUT.bsdf`: a measured file (any format brdfkit reads) or a
// model with parameters (MODEL --param ..., --params FILE [--material NAME]) written as a MERL
// .binary table (measured/merl_tabulate.h; cells the source has no value for become "not
// measured") or as an RGL tensor_file (measured/rgl_writer.h: Dupuy & Jakob 2018's
// parameterization, readable by Mitsuba 3's `measured` and pbrt-v4), isotropic or anisotropic as
// the source is (measured/azimuthal_symmetry.h) unless told. Written atomically.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/azimuthal_symmetry.h"
#include "brdfkit/measured/load.h"
#include "brdfkit/measured/merl.h"
#include "brdfkit/measured/write_measured.h"
#include "brdfkit/models/tabulate_brdf.h"
#include "brdf_options.h"
#include "command.h"

namespace brdfkit::cli {
namespace {

struct ConvertArgs {
  BrdfOptions source;
  std::string output;
  MeasuredWriteRequest request;
};

bool names_measured_file(const BrdfOptions& o) {
  return o.params.empty() && o.params_file.empty() && has_measured_extension(o.model);
}

int run_convert(const ConvertArgs& a) {
  const std::filesystem::path out(a.output);
  const std::string ext = out.extension().string();
  if (ext != ".binary" && ext != ".bsdf")
    throw InputError("-o", fmt::format("'{}': the output format comes from its extension, .binary (MERL) or .bsdf (RGL)",
                                       a.output));
  if (a.source.model.empty()) throw InputError("SOURCE", "a measured file or a model is required");
  std::unique_ptr<MeasuredBrdf> data;
  std::unique_ptr<Brdf> model;
  if (names_measured_file(a.source)) data = load_measured(a.source.model);
  else model = std::make_unique<Brdf>(a.source.brdf());
  const std::string what = data ? data->path() : std::string(model->model().name());
  const RglSource source = [&](const Vec3d& wi, const Vec3d& wo) {
    return data ? data->eval(wi, wo) : std::optional<Rgb>(model->eval(wi, wo));
  };
  const Warn warn = [](const std::string& w) { std::cerr << "warning: " << w << "\n"; };
  std::string layout = "MERL";
  if (model && ext == ".binary") {
    if (azimuthal_symmetry(source) != AzimuthalSymmetry::Isotropic) warn(kMerlDropsAnisotropy);
    merl::write(out, tabulate_brdf(*model, false).table);  // refuses negative values, as `tabulate` does
  } else {
    MeasuredWriteRequest request = a.request;
    if (request.description.empty()) request.description = fmt::format("converted by brdfkit from {}", what);
    layout = write_measured(out, source, request, warn);
  }
  std::cout << fmt::format("wrote {}: {} as {}\n", a.output, what, layout);
  return 0;
}

const CommandRegistration reg("convert", [](CLI::App& app) {
  auto* sub = app.add_subcommand("convert",
                                 "Write a measured file or a model (MODEL --param ..., or --params FILE) as MERL "
                                 ".binary or RGL .bsdf (the format from -o's extension)");
  auto a = std::make_shared<ConvertArgs>();
  add_brdf_options(sub, a->source);
  sub->add_option("-o,--output", a->output, "Output file: .binary (MERL) or .bsdf (RGL), written atomically")->required();
  sub->add_option("--description", a->request.description, "RGL: the file's description text");
  sub->add_option("--theta-i", a->request.theta_i, "RGL: incidence nodes from 0 to 90 degrees")->capture_default_str();
  sub->add_option("--grid", a->request.grid, "RGL: colour grid per incidence node (N x N); default 64, 32 for an anisotropic file");
  sub->add_option("--phi-i", a->request.phi_i,
                  "RGL: incidence azimuth nodes; 1 writes an isotropic file; default 1 for an isotropic source, "
                  "24 steps around the circle for an anisotropic one");
  sub->add_option("--symmetry", a->request.symmetry,
                  "RGL, anisotropic: 1 stores every incidence azimuth, 2 half of them (the source unchanged by a half turn), "
                  "4 a quarter (also by mirrors about x and y); default: probed from the source")
      ->check(CLI::IsMember({1, 2, 4}));
  return [a]() { return run_convert(*a); };
});

}  // namespace
}  // namespace brdfkit::cli
