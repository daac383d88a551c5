// `brdfkit tabulate MODEL [--param name=value ...] -o FILE.binary` and
// `brdfkit tabulate --params fit.json|published.json [--material NAME] -o FILE.binary`: any model
// with given parameters as a MERL-format file (DESIGN.md §2; measured/merl_tabulate.h fills every
// cell by index at its centre, cells below the horizon are written as raw −1), written
// atomically. A BRDF that is not finite, or negative, in any cell above the horizon is refused
// with the number of such cells: a negative value would silently become a "not measured" cell.
// `--clamp-negative` stores max(0, ρ) instead and says how many cells it clamped.
#include <fmt/format.h>

#include <iostream>
#include <nlohmann/json.hpp>

#include "brdfkit/core/error.h"
#include "brdfkit/core/json_text.h"
#include "brdfkit/measured/merl.h"
#include "brdfkit/models/tabulate_brdf.h"
#include "brdf_options.h"
#include "command.h"

namespace brdfkit::cli {
namespace {

struct TabulateArgs {
  BrdfOptions brdf;
  std::string output;
  bool clamp_negative = false;
  bool json = false;
};

int run_tabulate(const TabulateArgs& a) {
  if (a.output.empty()) throw InputError("-o", "an output file is required");
  const Brdf brdf = a.brdf.brdf();
  const BrdfTable t = tabulate_brdf(brdf, a.clamp_negative);
  merl::write(a.output, t.table);
  const Rgb& peak = t.max_rho;
  const size_t negative = t.clamped;
  const size_t valid = t.table.valid_count();
  if (a.json) {
    nlohmann::json out = {{"output", a.output},
                          {"model", brdf.model().name()},
                          {"cells", merl::kCellCount},
                          {"cells_written", valid},
                          {"cells_below_horizon", merl::kCellCount - valid},
                          {"cells_clamped", negative},
                          {"max_rho", {peak[0], peak[1], peak[2]}}};
    if (!a.brdf.material.empty()) out["material"] = a.brdf.material;
    std::cout << json_text(out) << "\n";
    return 0;
  }
  std::cout << fmt::format("wrote {}: {}{}\n", a.output, brdf.model().name(),
                           a.brdf.material.empty() ? "" : " (material " + a.brdf.material + ")");
  std::cout << fmt::format("cells   {} written, {} below the horizon (raw -1){}\n", valid, merl::kCellCount - valid,
                           negative > 0 ? fmt::format(", {} clamped from negative to 0", negative) : "");
  std::cout << fmt::format("max rho {:.6g} {:.6g} {:.6g} (1/sr)\n", peak[0], peak[1], peak[2]);
  return 0;
}

const CommandRegistration reg("tabulate", [](CLI::App& app) {
  auto* sub = app.add_subcommand(
      "tabulate",
      "Write a model with given parameters (MODEL --param ..., or --params FILE [--material NAME]) as a MERL-format "
      ".binary file");
  auto a = std::make_shared<TabulateArgs>();
  add_brdf_options(sub, a->brdf);
  sub->add_option("-o,--output", a->output, "Output MERL .binary file (written atomically)")->required();
  sub->add_flag("--clamp-negative", a->clamp_negative, "Store negative BRDF values as 0 instead of refusing");
  sub->add_flag("--json", a->json, "Print JSON");
  return [a]() { return run_tabulate(*a); };
});

}  // namespace
}  // namespace brdfkit::cli
