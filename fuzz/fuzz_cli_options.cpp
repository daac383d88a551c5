// libFuzzer target: the command line's numeric options and arguments. The CLI's parser lives in
// main() (apps/brdfkit/main.cpp) and cannot be called, so this target declares the options of
// `fit`, `eval` and `tabulate` as those commands do, parses the input as argv (arguments separated
// by NUL bytes) and hands the values to the library calls the commands make first:
// FitSettings::validate (fit/settings), fit::brdf_from_arguments (model names, sums, --param) and
// an evaluation at the parsed directions. Every argument also goes through parse_numbers, the
// number parser of the text formats (measured/text_numbers.h).
//
// `eval` and `tabulate` use the commands' own helper (apps/brdfkit/brdf_options.h). The FitSettings
// options are declared here as apps/brdfkit/fit_options.h declares them, with the same flags and
// fields: that header lists the fitting procedures, whose registry brings in fit/engine, which
// clang 14 cannot compile (fit/engine/linear_structure.cpp captures a structured binding in a
// lambda, C++20 P1091, clang >= 16). For the same reason --procedure is parsed but not looked up.
// --params files are left to fuzz_fit_record and fuzz_published_fits: here a path would name
// arbitrary files of the machine.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "brdf_options.h"
#include "brdfkit/fit/settings/fit_settings.h"
#include "brdfkit/measured/text_numbers.h"
#include "fuzz_input.h"

using namespace brdfkit;

namespace {

struct Parsed {
  fit::FitSettings settings;
  std::string file, model, output, report;
  cli::BrdfOptions brdf;
  std::vector<double> wi, wo;
  bool radians = false, flag = false;
};

// The options of apps/brdfkit/fit_options.h add_fit_settings (see the top of the file).
void add_fit_settings(CLI::App& sub, fit::FitSettings& s) {
  auto* procedure = sub.add_option("--procedure", s.procedure);
  auto* metric = sub.add_option("--metric", s.metric);
  procedure->excludes(metric);
  sub.add_flag("--per-channel-shape", s.per_channel_shape);
  sub.add_option("--starts", s.starts);
  sub.add_option("--seed", s.seed);
  sub.add_option("--max-iterations", s.max_iterations);
  sub.add_option("--coarsen", s.coarsen);
  sub.add_option("--threshold", s.threshold);
}

// `brdfkit` with the three subcommands' options; the subcommands, in the order fit, eval, tabulate.
std::vector<CLI::App*> make_app(CLI::App& app, Parsed& p) {
  app.require_subcommand(1);
  CLI::App* fit = app.add_subcommand("fit");
  fit->add_option("FILE", p.file)->required();
  fit->add_option("--model,-m", p.model);
  add_fit_settings(*fit, p.settings);
  fit->add_option("--report", p.report);
  fit->add_option("-o,--output", p.output)->required();
  CLI::App* eval = app.add_subcommand("eval");
  cli::add_brdf_options(eval, p.brdf);
  eval->add_option("--wi", p.wi)->required()->delimiter(',')->expected(2);
  eval->add_option("--wo", p.wo)->required()->delimiter(',')->expected(2);
  eval->add_flag("--radians,!--degrees", p.radians);
  CLI::App* tabulate = app.add_subcommand("tabulate");
  cli::add_brdf_options(tabulate, p.brdf);
  tabulate->add_option("-o,--output", p.output)->required();
  tabulate->add_flag("--clamp-negative", p.flag);
  return {fit, eval, tabulate};
}

// (θ, φ) as cmd_eval.cpp reads them, or nullopt where it refuses them.
std::optional<Vec3d> direction(const std::vector<double>& a, bool radians) {
  if (a.size() != 2 || !std::isfinite(a[0]) || !std::isfinite(a[1])) return std::nullopt;
  const double to_rad = radians ? 1.0 : kPi / 180.0, theta = a[0] * to_rad;
  if (!(theta >= 0 && theta <= kPi / 2 + 1e-12)) return std::nullopt;
  return spherical_direction(std::min(theta, kPi / 2), a[1] * to_rad);
}

void run(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  CLI::App app("brdfkit");
  Parsed p;
  const std::vector<CLI::App*> subs = make_app(app, p);
  try {
    app.parse(int(argv.size()), argv.data());
  } catch (const CLI::ParseError&) {
    return;  // main() prints it in one line and exits 2
  }
  if (subs[0]->parsed()) {
    p.settings.validate();
    if (!p.model.empty()) (void)model_by_name(p.model);
    return;
  }
  if (!p.brdf.params_file.empty()) return;
  const Brdf brdf = p.brdf.brdf();
  if (subs[1]->parsed()) {
    const auto wi = direction(p.wi, p.radians), wo = direction(p.wo, p.radians);
    if (wi && wo) (void)brdf.eval(*wi, *wo);
  } else {
    for (const auto& [wi, wo] : fuzz::direction_pairs()) (void)brdf.eval(wi, wo);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  std::vector<std::string> args{"brdfkit"};
  std::string current;
  for (size_t k = 0; k < size; ++k) {
    if (data[k] == 0) {
      args.push_back(current);
      current.clear();
    } else {
      current.push_back(char(data[k]));
    }
  }
  args.push_back(current);
  for (size_t k = 1; k < args.size(); ++k) fuzz::expect_input_errors([&] { (void)parse_numbers(args[k], "argument"); });
  fuzz::expect_input_errors([&] { run(args); });
  return 0;
}
