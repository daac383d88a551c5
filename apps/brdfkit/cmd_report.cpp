// `brdfkit report RESULTS_DIR [-o SITE_DIR] [--env MAP.exr] …`: the static HTML site of a fit-all
// folder (report/report_site.h); prints the path of its index.html.
#include <fmt/format.h>

#include <chrono>
#include <iostream>

#include "brdfkit/core/error.h"
#include "brdfkit/report/report_site.h"
#include "command.h"

namespace brdfkit::cli {
namespace {

namespace fs = std::filesystem;

struct ReportArgs {
  std::string results, output, env;
  double env_rotation = 0;
  int size = 192, spp = 64, fits = 3;
  std::uint64_t seed = 1;
  bool quiet = false;
};

int run_report(const ReportArgs& a) {
  if (a.size < 8 || a.size > 2048) throw InputError("--size", "must be between 8 and 2048");
  if (a.spp < 1) throw InputError("--spp", "must be >= 1");
  if (a.fits < 1) throw InputError("--fits", "must be >= 1");
  const auto t0 = std::chrono::steady_clock::now();
  const report::BatchResults results = report::load_batch_results(a.results);
  report::ReportOptions opt;
  opt.out_dir = a.output.empty() ? fs::path(a.results) / "report" : fs::path(a.output);
  if (!a.env.empty()) opt.env = a.env;
  opt.env_rotation = a.env_rotation;
  opt.size = a.size;
  opt.spp = a.spp;
  opt.fits_shown = a.fits;
  opt.seed = a.seed;
  if (!a.quiet) opt.log = [](std::string_view line) { std::cerr << line << std::endl; };
  const fs::path index = report::write_report(results, opt);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!a.quiet) std::cerr << fmt::format("report: {} materials in {:.1f} s\n", results.materials.size(), secs);
  std::cout << fs::absolute(index).lexically_normal().string() << "\n";
  return 0;
}

const CommandRegistration reg("report", [](CLI::App& app) {
  auto* sub = app.add_subcommand("report", "Static HTML report (opens offline) of a fit-all folder: error table and chart, "
                                           "seed claims, per-material renders, plots and parameters");
  auto a = std::make_shared<ReportArgs>();
  sub->add_option("RESULTS_DIR", a->results, "A fit-all output folder (<material>/<model>.json)")->required();
  sub->add_option("-o,--output", a->output, "Site folder (default RESULTS_DIR/report)");
  sub->add_option("--env", a->env, "Environment map (.exr/.hdr) for the renders (default: the built-in lights)");
  sub->add_option("--env-rotation", a->env_rotation, "Turn the map about the vertical axis (degrees)")->capture_default_str();
  sub->add_option("--size", a->size, "Render size in pixels")->capture_default_str();
  sub->add_option("--spp", a->spp, "Render samples per pixel")->capture_default_str();
  sub->add_option("--fits", a->fits, "Best fits rendered and plotted per material")->capture_default_str();
  sub->add_option("--seed", a->seed, "Render seed")->capture_default_str();
  sub->add_flag("--quiet,-q", a->quiet, "No progress on stderr");
  return [a]() { return run_report(*a); };
});

}  // namespace
}  // namespace brdfkit::cli
