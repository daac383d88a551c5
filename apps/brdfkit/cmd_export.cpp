// `brdfkit export FIT.json --to gltf|mitsuba3|pbrt-v4|brdf-explorer|glsl -o FILE [--json]`: writes
// a fit as a renderer's material (glTF, Mitsuba 3 XML + sphere scene, pbrt-v4 + sphere scene), a
// BRDF Explorer .brdf or a GLSL function (export/export_fit.h). A fit in the target's own model is
// written exactly; any other is refitted into the target's model on the MERL grid under the fit's
// metric, and the added error is printed and written into the file.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "brdfkit/core/json_text.h"
#include "brdfkit/export/export_fit.h"
#include "brdfkit/fit/param_source.h"
#include "command.h"

namespace brdfkit::cli {
namespace {

struct ExportArgs {
  std::string file, material, to, output;
  bool json = false;
};

int run_export(const ExportArgs& a) {
  const exporter::Target target = exporter::parse_target(a.to);
  const fit::LoadedParams loaded = fit::load_params(a.file, a.material);
  const exporter::ExportResult r = exporter::export_fit(loaded.brdf, loaded.record, target, a.output);
  const exporter::Provenance& p = r.provenance;
  if (a.json) {
    nlohmann::json j = exporter::provenance_json(p);
    for (const auto& f : r.files) j["files"].push_back(f.string());
    std::cout << json_text(j) << "\n";
    return 0;
  }
  std::cout << fmt::format("target     {}\n", p.target);
  std::cout << fmt::format("model      {}{}\n", p.model, p.refitted ? " (refitted from " + p.source_model + ")" : "");
  if (p.source_error) std::cout << fmt::format("fit error  {} {:.6g} against the measurement\n", p.metric, *p.source_error);
  if (p.refitted)
    std::cout << fmt::format("added      {} {:.6g} (refit against the tabulated {} fit, {:.1f} s)\n", p.metric,
                             p.added_error.value_or(0.0), p.source_model, r.refit_seconds);
  else
    std::cout << "added      0 (the fit's own model, exported exactly)\n";
  for (const auto& f : r.files) std::cout << fmt::format("wrote      {}\n", f.string());
  return 0;
}

const CommandRegistration reg("export", [](CLI::App& app) {
  auto* sub = app.add_subcommand("export", "Write a fit as a glTF, Mitsuba 3, pbrt-v4, BRDF Explorer or GLSL material");
  auto a = std::make_shared<ExportArgs>();
  sub->add_option("FIT", a->file, "A fit JSON written by `brdfkit fit` (or a published-fits file with --material)")
      ->required();
  sub->add_option("--material", a->material, "The material of a published-fits file");
  sub->add_option("--to", a->to, "gltf, mitsuba3, pbrt-v4, brdf-explorer or glsl")->required();
  sub->add_option("-o,--output", a->output,
                  "The file to write (Mitsuba 3 and pbrt-v4 also write <stem>_scene.<ext> beside it)")
      ->required();
  sub->add_flag("--json", a->json, "Print what was written as JSON");
  return [a]() { return run_export(*a); };
});

}  // namespace
}  // namespace brdfkit::cli
