// `brdfkit fit FILE --model M [--procedure P | --metric X] [--per-channel-shape] [--starts N]
// [--seed S] -o fit.json [--json]`: fits a model to measured data, either with a procedure of
// DESIGN.md §8 (whose metric is the fitting metric) or as a plain fit under a metric (variable
// projection for the colours, bounded Ceres for the shape, seeded multi-start), prints the
// parameters, every metric's value, iterations and time, and saves the fit atomically as JSON
// (fit/fit_job.h, the same code `fit-all` runs for each material × model). `--for gltf|mitsuba3|
// pbrt-v4` fits the target renderer's own model (its default, or --model among its models) and
// exports it in one step (export/export_fit.h), to --export-output or the fit's path with the
// target's extension.
#include <fmt/format.h>

#include <future>
#include <iostream>
#include <memory>

#include "brdfkit/core/atomic_file.h"
#include "brdfkit/core/error.h"
#include "brdfkit/core/file_digest.h"
#include "brdfkit/core/json_text.h"
#include "brdfkit/export/export_fit.h"
#include "brdfkit/fit/fit_job.h"
#include "brdfkit/fit/metric/metric_report.h"
#include "brdfkit/fit/metric/metric_store.h"
#include "brdfkit/fit/procedure/search_box.h"
#include "brdfkit/measured/load.h"
#include "command.h"
#include "fit_options.h"

namespace brdfkit::cli {
namespace {

struct FitArgs {
  std::string file, model, output, report, for_target, export_output;
  fit::FitSettings settings;
  bool json = false, verbose = false;
};

// The model a fit `--for` a renderer fits: --model when it is one of the target's, else its default.
const Model& model_for(const FitArgs& a) {
  if (a.for_target.empty()) {
    if (a.model.empty()) throw SettingError("model", "required (or --for gltf|mitsuba3|pbrt-v4)");
    return model_by_name(a.model);
  }
  const exporter::Target t = exporter::parse_target(a.for_target, "--for");
  if (t == exporter::Target::Glsl || t == exporter::Target::BrdfExplorer)
    throw SettingError("for", "takes a renderer: gltf, mitsuba3 or pbrt-v4 (glsl and brdf-explorer write any model: "
                              "use export)");
  if (a.model.empty()) return exporter::default_model(t);
  const Model& m = model_by_name(a.model);
  if (!exporter::exports_exactly(t, m, ParamValues::defaults(m.params())))
    throw SettingError("model", a.model + " is not a model of --for " + a.for_target);
  return m;
}

std::filesystem::path export_path(const FitArgs& a) {
  if (!a.export_output.empty()) return a.export_output;
  const exporter::Target t = exporter::parse_target(a.for_target, "--for");
  std::filesystem::path p = a.output;
  return p.replace_extension(t == exporter::Target::Gltf ? ".gltf" : t == exporter::Target::Mitsuba3 ? ".xml" : ".pbrt");
}

void print_summary(const fit::FitJobResult& r, const FitArgs& a, const Model& model,
                   const std::vector<std::filesystem::path>& exported) {
  const fit::FitRecord& rec = r.record;
  const fit::FitSettings& s = a.settings;
  std::cout << fmt::format("model      {}\n", rec.model);
  std::cout << fmt::format("data       {} (sha256 {})\n", rec.data_file, rec.data_sha256);
  std::cout << fmt::format("fit        {}, {} shape, {} start(s) from seed {}, best start {}, {} iterations, {:.3f} s, {}\n",
                           s.procedure.empty() ? "plain fit under metric " + rec.fit_metric
                                               : "procedure " + s.procedure + " (metric " + rec.fit_metric + ")",
                           s.per_channel_shape ? "per-channel" : "shared", s.starts, s.seed, r.fit.best_start,
                           rec.iterations, rec.seconds, rec.converged ? "converged" : "not converged: " + rec.message);
  for (const std::string& step : r.steps) std::cout << fmt::format("  step     {}\n", step);
  std::cout << "parameters\n" << fit::format_params(model, rec.values);
  std::cout << "metrics\n" << fit::format_metrics(rec.metrics);
  std::cout << fmt::format("saved      {}\n", a.output);
  for (const auto& f : exported) std::cout << fmt::format("exported   {}\n", f.string());
}

int run_fit(const FitArgs& a) {
  const Model& model = model_for(a);
  const std::vector<std::string> report = fit::parse_metric_list(a.report);
  fit::validate(a.settings);  // names a bad setting before any work
  const Model* const models[] = {&model};
  fit::check_search_bounds(models, a.settings.bounds);
  check_output_file(a.output);  // and an output that cannot be written, before a fit of minutes
  if (!a.for_target.empty()) check_output_file(export_path(a));
  // The digest reads the file once more: on its own thread, while the data load and the domains build.
  std::future<std::string> sha256 = std::async(std::launch::async, [&] { return sha256_file(a.file); });
  const auto data = load_measured(a.file);
  // The fit and the reports share the metric domains they have in common (ngan, its albedo norm).
  fit::MetricStore store(*data);
  fit::Progress progress;
  if (a.verbose) progress = [](std::string_view line) { std::cerr << line << std::endl; };
  fit::FitJobResult r;
  try {
    r = fit::fit_and_report(model, store, a.file, sha256.get(), a.settings, report, progress);
  } catch (const fit::FitError& e) {
    std::cerr << "brdfkit: fit failed: " << e.what() << "\n";
    return 1;
  }
  const std::string doc = json_text(fit::fit_job_json(r, a.settings)) + "\n";
  write_file_atomically(a.output, doc);
  std::vector<std::filesystem::path> exported;
  if (!a.for_target.empty())
    exported = exporter::export_fit(Brdf(model, r.record.values), r.record,
                                    exporter::parse_target(a.for_target, "--for"), export_path(a))
                   .files;
  if (a.json) std::cout << doc;
  else print_summary(r, a, model, exported);
  return 0;
}

const CommandRegistration reg("fit", [](CLI::App& app) {
  auto* sub = app.add_subcommand("fit", "Fit a model to measured reflectance and save the fit as JSON");
  auto a = std::make_shared<FitArgs>();
  sub->add_option("FILE", a->file, "Measured BRDF (MERL .binary, RGL .bsdf, ...)")->required();
  sub->add_option("--model,-m", a->model, "Model to fit (see `brdfkit models`); with --for, one of the target's");
  sub->add_option("--for", a->for_target,
                  "Fit the renderer's own model (gltf, mitsuba3, pbrt-v4) and export it in one step");
  sub->add_option("--export-output", a->export_output,
                  "With --for: the exported file (default: the fit's path with .gltf, .xml or .pbrt)");
  add_fit_settings(*sub, a->settings);
  sub->add_option("--report", a->report, "Comma-separated metrics to report (default: all)");
  sub->add_option("-o,--output", a->output, "Where to write the fit (JSON, written atomically)")->required();
  sub->add_flag("--json", a->json, "Print the saved JSON instead of a summary");
  sub->add_flag("--verbose,-v", a->verbose, "Print the procedure's steps on stderr as they run");
  return [a]() { return run_fit(*a); };
});

}  // namespace
}  // namespace brdfkit::cli
