// `brdfkit error FILE --params fit.json [--metric X] [--json]` or
// `brdfkit error FILE --params PUBLISHED.json --material NAME`: recomputes the metrics of a saved
// fit — or of a published fit (DESIGN.md §10) — on measured data; prints them exactly as `fit`
// did (same grids, same order of summation).
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "brdfkit/core/file_digest.h"
#include "brdfkit/core/json_text.h"
#include "brdfkit/fit/fit_record.h"
#include "brdfkit/fit/metric/metric_report.h"
#include "brdfkit/fit/param_source.h"
#include "brdfkit/measured/load.h"
#include "command.h"

namespace brdfkit::cli {
namespace {

struct ErrorArgs {
  std::string file, params, material, metric;
  int coarsen = 0;  // 0: the saved fit's
  bool json = false;
};

int run_error(const ErrorArgs& a) {
  const fit::LoadedParams loaded = fit::load_params(a.params, a.material);
  const Model& model = loaded.brdf.model();
  const std::vector<std::string> ids = fit::parse_metric_list(a.metric, "metric");
  if (a.coarsen < 0) throw SettingError("coarsen", "must be >= 1 (0: the saved fit's)");
  const int saved_coarsen = loaded.record ? loaded.record->coarsen : 1;
  const int coarsen = a.coarsen > 0 ? a.coarsen : saved_coarsen;
  const auto data = load_measured(a.file);
  const std::string sha = sha256_file(a.file);
  if (loaded.record && !loaded.record->data_sha256.empty() && loaded.record->data_sha256 != sha)
    std::cerr << fmt::format("brdfkit: warning: {} is not the file this fit was made on (sha256 {} != {})\n", a.file,
                             sha, loaded.record->data_sha256);
  fit::MetricStore store(*data);
  const auto metrics = fit::report_metrics(store, model, loaded.brdf.values(), ids, {coarsen});
  if (a.json) {
    nlohmann::json out = {{"model", std::string(model.name())}, {"data", {{"file", a.file}, {"sha256", sha}}},
                          {"grid_coarsen", coarsen}, {"metrics", nlohmann::json::object()}};
    if (!loaded.material.empty()) out["published"] = {{"file", a.params}, {"material", loaded.material}};
    for (const auto& m : metrics) {
      if (m.value) out["metrics"][m.id] = *m.value;
      else out["metrics"][m.id] = nullptr;
    }
    std::cout << json_text(out) << "\n";
    return 0;
  }
  std::cout << fmt::format("model      {}\n", model.name());
  if (!loaded.material.empty())
    std::cout << fmt::format("published  {} (material {})\n", a.params, loaded.material);
  std::cout << fmt::format("data       {} (sha256 {})\n", a.file, sha);
  std::cout << "parameters\n" << fit::format_params(model, loaded.brdf.values());
  std::cout << "metrics\n" << fit::format_metrics(metrics);
  return 0;
}

const CommandRegistration reg("error", [](CLI::App& app) {
  auto* sub = app.add_subcommand("error", "Recompute the error metrics of a saved or published fit on measured data");
  auto a = std::make_shared<ErrorArgs>();
  sub->add_option("FILE", a->file, "Measured BRDF")->required();
  sub->add_option("--params,-p", a->params, "A fit saved by `brdfkit fit`, or a published-fits file (with --material)")
      ->required();
  sub->add_option("--material", a->material, "The material of a published-fits file (e.g. alum-bronze)");
  sub->add_option("--metric", a->metric, "Comma-separated metrics (default: all)");
  sub->add_option("--coarsen", a->coarsen, "Grid coarsening (default: the one the fit was saved with)");
  sub->add_flag("--json", a->json, "Print JSON");
  return [a]() { return run_error(*a); };
});

}  // namespace
}  // namespace brdfkit::cli
