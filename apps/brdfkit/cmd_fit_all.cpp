// `brdfkit fit-all DIR|FILES... --models M1,M2,…|all|single-lobe [--procedure P | --metric X]
//  -o OUTDIR [--jobs N] [--compare PUBLISHED.json]`: fits every material × model (fit/batch/fit_batch.h),
// one progress line per finished fit on stderr, the table of the fitting metric's error on stdout,
// OUTDIR/<material>/<model>.json, summary.csv and table.txt. Several may share OUTDIR at once
// (claims: fit/batch/fit_batch.h). Exit codes: 0 every fit saved (or running in another process),
// 1 a fit failed or is unfinished, 2 bad input or an output that cannot be written (the message
// names the file), 130 interrupted by Ctrl-C (fits in flight are finished and saved, the summary
// marks the rest unfinished; a second Ctrl-C ends the process at once).
#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <iostream>
#include <memory>

#include "brdfkit/core/json_text.h"
#include "brdfkit/fit/batch/fit_batch.h"
#include "brdfkit/fit/metric/metric_report.h"
#include "brdfkit/fit/procedure/search_box.h"
#include "brdfkit/models/model_sets.h"
#include "brdfkit/models/published_fits.h"
#include "command.h"
#include "fit_options.h"

namespace brdfkit::cli {
namespace {

constexpr int kInterrupted = 130;  // 128 + SIGINT, what a shell reports for a process Ctrl-C ended

std::atomic<bool> interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

// Async-signal-safe: sets the flag and writes one line with write(2). SA_RESETHAND restores the
// default action, so a second Ctrl-C ends the process without waiting for the fits in flight.
void on_interrupt(int) {
  interrupted.store(true);
  static const char msg[] = "\nfit-all: interrupted: finishing the fits in flight; Ctrl-C again abandons them\n";
  if (::write(STDERR_FILENO, msg, sizeof msg - 1) < 0) return;
}

void stop_on_interrupt() {
  struct sigaction sa = {};
  sa.sa_handler = on_interrupt;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &sa, nullptr);
}

struct FitAllArgs {
  std::vector<std::string> inputs;
  std::string models = "single-lobe", output, report = "ngan,bagher,low-e1,low-e2";
  fit::BatchSettings settings;
  bool json = false;
};

int run_fit_all(FitAllArgs& a) {
  const std::vector<const Model*> models = parse_model_set(a.models);
  a.settings.report = a.report == "all" ? fit::metric_ids() : fit::parse_metric_list(a.report);
  a.settings.validate();
  fit::check_search_bounds(models, a.settings.fit.bounds);
  if (!a.settings.compare.empty()) {  // refused before the batch is announced, as every other bad option
    const PublishedFits published = PublishedFits::read(a.settings.compare);
    if (!published.supported()) throw InputError(a.settings.compare, published.unsupported_reason());
  }
  const auto inputs = fit::list_batch_inputs(a.inputs);
  std::cerr << fmt::format("fit-all: {} material(s) x {} model(s) = {} fits, {} at once, into {}\n", inputs.size(),
                           models.size(), inputs.size() * models.size(), a.settings.jobs, a.output);
  stop_on_interrupt();
  const fit::BatchSummary s = fit::run_fit_batch(
      inputs, models, a.output, a.settings, [](std::string_view line) { std::cerr << line << std::endl; }, &interrupted);
  if (a.json) std::cout << json_text(fit::summary_json(s)) << "\n";
  else std::cout << fit::summary_table(s);
  if (s.interrupted) return kInterrupted;
  return s.count(fit::FitStatus::Failed) + s.count(fit::FitStatus::Unfinished) > 0 ? 1 : 0;
}

const CommandRegistration reg("fit-all", [](CLI::App& app) {
  auto* sub = app.add_subcommand("fit-all", "Fit every material x model, resumable; summary CSV and error table");
  auto a = std::make_shared<FitAllArgs>();
  sub->add_option("INPUTS", a->inputs, "Measured files and/or folders (every .binary/.bsdf/.brdf/.alta in a folder)")
      ->required();
  sub->add_option("--models", a->models,
                  "Comma-separated model names, 'all' (the catalogue) or 'single-lobe' (models with exactly one "
                  "specular lobe: one per-channel linear lobe scale besides kd, see models/model_sets.h), 'renderer' "
                  "(the renderers' own BSDFs) or 'anisotropic' (lobes turned by a fitted tangent angle, and ward-aniso)")
      ->capture_default_str();
  add_fit_settings(*sub, a->settings.fit);
  sub->add_option("--report", a->report,
                  "Metrics saved and tabulated besides the fitting metric ('all' adds hp-rmse: ~17 s of CPU a fit on RGL)")
      ->capture_default_str();
  sub->add_option("--jobs,-j", a->settings.jobs,
                  "Fits run at once (each fit is itself multi-threaded; 1 to " +
                      std::to_string(fit::BatchSettings::kMaxJobs) + ")")
      ->capture_default_str();
  sub->add_option("--compare", a->settings.compare,
                  "A published-fits file: its fit's error under the fitting metric for materials of that name");
  sub->add_option("-o,--output", a->output, "Output folder (created; rerun with the same one to resume)")->required();
  sub->add_flag("--json", a->json, "Print the summary as JSON instead of the table");
  return [a]() { return run_fit_all(*a); };
});

}  // namespace
}  // namespace brdfkit::cli
