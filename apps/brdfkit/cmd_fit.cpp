// `brdfkit fit FILE --model M [--procedure P | --metric X] [--per-channel-shape] [--starts N]
// [--seed S] -o fit.json [--json]`: fits a model to measured data, either with a procedure of
// DESIGN.md §8 (whose metric is the fitting metric) or as a plain fit under a metric (variable
// projection for the colours, bounded Ceres for the shape, seeded multi-start), prints the
// parameters, every metric's value, iterations and time, and saves the fit atomically as JSON
// (fit/fit_job.h, the same code `fit-all` runs for each material × model).
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "brdfkit/core/atomic_file.h"
#include "brdfkit/core/file_digest.h"
#include "brdfkit/fit/fit_job.h"
#include "brdfkit/fit/metric/metric_report.h"
#include "brdfkit/fit/metric/metric_store.h"
#include "brdfkit/measured/load.h"
#include "command.h"
#include "fit_options.h"

namespace brdfkit::cli {
namespace {

struct FitArgs {
  std::string file, model, output, report;
  fit::FitSettings settings;
  bool json = false, verbose = false;
};

void print_summary(const fit::FitJobResult& r, const FitArgs& a, const Model& model) {
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
}

int run_fit(const FitArgs& a) {
  const Model& model = model_by_name(a.model);
  const std::vector<std::string> report = fit::parse_metric_list(a.report);
  fit::validate(a.settings);  // names a bad setting before any work
  const auto data = load_measured(a.file);
  // The fit and the reports share the metric domains they have in common (ngan, its albedo norm).
  fit::MetricStore store(*data);
  fit::Progress progress;
  if (a.verbose) progress = [](std::string_view line) { std::cerr << line << std::endl; };
  fit::FitJobResult r;
  try {
    r = fit::run_fit_job(model, store, a.file, sha256_file(a.file), a.settings, progress);
  } catch (const fit::FitError& e) {
    std::cerr << "brdfkit: fit failed: " << e.what() << "\n";
    return 1;
  }
  r.record.metrics = fit::report_metrics(store, model, r.record.values, report, fit::MetricOptions{a.settings.coarsen});
  const nlohmann::json doc = fit::fit_job_json(r, a.settings);
  write_file_atomically(a.output, doc.dump(2) + "\n");
  if (a.json) std::cout << doc.dump(2) << "\n";
  else print_summary(r, a, model);
  return 0;
}

const CommandRegistration reg("fit", [](CLI::App& app) {
  auto* sub = app.add_subcommand("fit", "Fit a model to measured reflectance and save the fit as JSON");
  auto a = std::make_shared<FitArgs>();
  sub->add_option("FILE", a->file, "Measured BRDF (MERL .binary, RGL .bsdf, ...)")->required();
  sub->add_option("--model,-m", a->model, "Model to fit (see `brdfkit models`)")->required();
  add_fit_settings(*sub, a->settings);
  sub->add_option("--report", a->report, "Comma-separated metrics to report (default: all)");
  sub->add_option("-o,--output", a->output, "Where to write the fit (JSON, written atomically)")->required();
  sub->add_flag("--json", a->json, "Print the saved JSON instead of a summary");
  sub->add_flag("--verbose,-v", a->verbose, "Print the procedure's steps on stderr as they run");
  return [a]() { return run_fit(*a); };
});

}  // namespace
}  // namespace brdfkit::cli
