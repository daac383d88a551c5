// `brdfkit fit FILE --model M [--metric X] [--starts N] [--seed S] -o fit.json [--json]`: fits a
// model to measured data (DESIGN.md §8: variable projection for the colours, bounded Ceres for
// the shape, seeded multi-start), prints the parameters, every metric's value, iterations and
// time, and saves the fit atomically as JSON (fit/fit_record.h).
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "brdfkit/fit/file_digest.h"
#include "brdfkit/fit/fit_record.h"
#include "brdfkit/fit/metric_report.h"
#include "brdfkit/fit/variable_projection.h"
#include "brdfkit/measured/load.h"
#include "command.h"

namespace brdfkit::cli {
namespace {

struct FitArgs {
  std::string file, model, metric = "ngan", output, report;
  int starts = 1, max_iterations = 100, coarsen = 1;
  std::uint64_t seed = 1;
  bool json = false;
};

int run_fit(const FitArgs& a) {
  const Model& model = model_by_name(a.model);
  const std::vector<std::string> report = fit::parse_metric_list(a.report);
  fit::parse_metric_list(a.metric);  // names the metric before any work
  const auto data = load_measured(a.file);
  const fit::MetricOptions opt{a.coarsen};
  const fit::Metric metric = fit::make_metric(a.metric, *data, opt);
  fit::FitResult result;
  try {
    result = fit::fit_model(model, metric, {a.starts, a.seed, a.max_iterations});
  } catch (const fit::FitError& e) {
    std::cerr << "brdfkit: fit failed: " << e.what() << "\n";
    return 1;
  }
  fit::FitRecord rec;
  rec.model = std::string(model.name());
  rec.values = result.values;
  rec.data_file = a.file;
  rec.data_sha256 = fit::sha256_file(a.file);
  rec.fit_metric = a.metric;
  rec.starts = a.starts;
  rec.seed = a.seed;
  rec.iterations = result.iterations;
  rec.seconds = result.seconds;
  rec.converged = result.converged;
  rec.message = result.message;
  rec.coarsen = a.coarsen;
  rec.metrics = fit::report_metrics(*data, model, result.values, report, opt);
  fit::save_fit_record(a.output, rec);
  if (a.json) {
    std::cout << fit::to_json(rec).dump(2) << "\n";
    return 0;
  }
  std::cout << fmt::format("model      {}\n", rec.model);
  std::cout << fmt::format("data       {} (sha256 {})\n", rec.data_file, rec.data_sha256);
  std::cout << fmt::format("fit        metric {}, {} start(s) from seed {}, best start {}, {} iterations, {:.3f} s, {}\n",
                           a.metric, a.starts, a.seed, result.best_start, result.iterations, result.seconds,
                           result.converged ? "converged" : "not converged: " + result.message);
  std::cout << "parameters\n" << fit::format_params(model, result.values);
  std::cout << "metrics\n" << fit::format_metrics(rec.metrics);
  std::cout << fmt::format("saved      {}\n", a.output);
  return 0;
}

const CommandRegistration reg("fit", [](CLI::App& app) {
  auto* sub = app.add_subcommand("fit", "Fit a model to measured reflectance and save the fit as JSON");
  auto a = std::make_shared<FitArgs>();
  sub->add_option("FILE", a->file, "Measured BRDF (MERL .binary, RGL .bsdf, ...)")->required();
  sub->add_option("--model,-m", a->model, "Model to fit (see `brdfkit models`)")->required();
  sub->add_option("--metric", a->metric, "Fitting metric: ngan, bagher, low-e1, low-e2 (hp-rmse is report-only)")
      ->capture_default_str();
  sub->add_option("--starts", a->starts, "Number of starts: the defaults, then seeded random ones")->capture_default_str();
  sub->add_option("--seed", a->seed, "Seed of the random starts")->capture_default_str();
  sub->add_option("--max-iterations", a->max_iterations, "Solver iterations per start")->capture_default_str();
  sub->add_option("--report", a->report, "Comma-separated metrics to report (default: all)");
  sub->add_option("--coarsen", a->coarsen,
                  "Widen every metric grid step by this factor (1 = the papers' grids; quick looks only)")
      ->capture_default_str();
  sub->add_option("-o,--output", a->output, "Where to write the fit (JSON, written atomically)")->required();
  sub->add_flag("--json", a->json, "Print the saved JSON instead of a summary");
  return [a]() { return run_fit(*a); };
});

}  // namespace
}  // namespace brdfkit::cli
