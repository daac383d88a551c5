// `brdfkit fit-all DIR|FILES... --models M1,M2,…|all|single-lobe [--procedure P | --metric X]
//  -o OUTDIR [--jobs N] [--compare PUBLISHED.json]`: fits every material × model (fit/fit_batch.h),
// one progress line per finished fit on stderr, the table of the fitting metric's error on stdout,
// OUTDIR/<material>/<model>.json, summary.csv and table.txt. Exit 1 when any fit failed.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "brdfkit/fit/batch/fit_batch.h"
#include "brdfkit/fit/metric/metric_report.h"
#include "brdfkit/models/model_sets.h"
#include "command.h"

namespace brdfkit::cli {
namespace {

struct FitAllArgs {
  std::vector<std::string> inputs;
  std::string models = "single-lobe", procedure, metric, output, report = "ngan,bagher,low-e1,low-e2", compare;
  int starts = 1, max_iterations = 100, coarsen = 1, jobs = 1;
  std::uint64_t seed = 1;
  bool per_channel_shape = false, json = false;
};

int run_fit_all(const FitAllArgs& a) {
  const std::vector<const Model*> models = parse_model_set(a.models);
  fit::BatchOptions opt;
  opt.job.procedure = a.procedure;
  opt.job.metric = a.metric;
  opt.job.per_channel_shape = a.per_channel_shape;
  opt.job.starts = a.starts;
  opt.job.seed = a.seed;
  opt.job.max_iterations = a.max_iterations;
  opt.job.coarsen = a.coarsen;
  opt.report = a.report == "all" ? std::vector<std::string>{} : fit::parse_metric_list(a.report);
  if (a.report == "all")
    for (auto id : fit::metric_ids()) opt.report.emplace_back(id);
  opt.jobs = a.jobs;
  opt.compare = a.compare;
  opt.log = [](std::string_view line) { std::cerr << line << std::endl; };
  fit::validate(opt.job);
  const auto inputs = fit::list_batch_inputs(a.inputs);
  std::cerr << fmt::format("fit-all: {} material(s) x {} model(s) = {} fits, {} at once, into {}\n", inputs.size(),
                           models.size(), inputs.size() * models.size(), a.jobs, a.output);
  const fit::BatchSummary s = fit::run_fit_batch(inputs, models, a.output, opt);
  if (a.json) std::cout << fit::summary_json(s).dump(2) << "\n";
  else std::cout << fit::summary_table(s);
  return s.count(fit::FitStatus::Failed) > 0 ? 1 : 0;
}

const CommandRegistration reg("fit-all", [](CLI::App& app) {
  auto* sub = app.add_subcommand("fit-all", "Fit every material x model, resumable; summary CSV and error table");
  auto a = std::make_shared<FitAllArgs>();
  sub->add_option("INPUTS", a->inputs, "Measured files and/or folders (every .binary/.bsdf/.brdf/.alta in a folder)")
      ->required();
  sub->add_option("--models", a->models,
                  "Comma-separated model names, 'all' (the catalogue) or 'single-lobe' (models with exactly one "
                  "specular lobe: one per-channel linear lobe scale besides kd, see models/model_sets.h) or 'renderer' "
                  "(the renderers' own BSDFs)")
      ->capture_default_str();
  auto* proc = sub->add_option("--procedure", a->procedure,
                               "Fitting procedure: ngan, bagher, low-e1, low-e2, hp-2step, hp-1step (DESIGN.md §8)");
  auto* metric = sub->add_option("--metric", a->metric, "Plain fit under this metric (default ngan)");
  proc->excludes(metric);
  sub->add_flag("--per-channel-shape", a->per_channel_shape, "Fit the lobe shape per channel instead of shared");
  sub->add_option("--starts", a->starts, "Starts per fit: the defaults, then seeded random ones")->capture_default_str();
  sub->add_option("--seed", a->seed, "Seed of the random starts")->capture_default_str();
  sub->add_option("--max-iterations", a->max_iterations, "Solver iterations per start")->capture_default_str();
  sub->add_option("--coarsen", a->coarsen, "Widen every metric grid step by this factor (quick looks and tests only)")
      ->capture_default_str();
  sub->add_option("--report", a->report,
                  "Metrics saved and tabulated besides the fitting metric ('all' adds hp-rmse: ~17 s of CPU a fit on RGL)")
      ->capture_default_str();
  sub->add_option("--jobs,-j", a->jobs, "Fits run at once (each fit is itself multi-threaded)")->capture_default_str();
  sub->add_option("--compare", a->compare,
                  "A published-fits file: its fit's error under the fitting metric for materials of that name");
  sub->add_option("-o,--output", a->output, "Output folder (created; rerun with the same one to resume)")->required();
  sub->add_flag("--json", a->json, "Print the summary as JSON instead of the table");
  return [a]() { return run_fit_all(*a); };
});

}  // namespace
}  // namespace brdfkit::cli
