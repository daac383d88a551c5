#pragma once
// Where a model's parameter values come from on the command line: `--param name=value`
// arguments, a fit JSON written by `brdfkit fit` (DESIGN.md §1), or a published-fits file of
// ../shared/data/published-fits/ with one of its materials (DESIGN.md §10). Shared by `check`,
// `eval`, `tabulate` and `error`, so every command reads parameters the same way.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "brdfkit/fit/fit_record.h"
#include "brdfkit/models/model.h"

namespace brdfkit::fit {

// Applies one `--param` argument to `values`:
//   name=value         all channels (the only form a shared parameter accepts)
//   name[r|g|b]=value  one channel (also name[0|1|2]=value)
//   name=r,g,b         three channels, e.g. kd=0.1,0.2,0.3
// InputError naming the argument for bad syntax, a non-finite number, an unknown parameter or a
// value outside the parameter's bounds.
void apply_param(const ParamTable& table, ParamValues& values, const std::string& arg);

// The table's defaults with every argument applied in order.
ParamValues params_from_args(const ParamTable& table, const std::vector<std::string>& args);

struct LoadedParams {
  Brdf brdf;
  std::optional<FitRecord> record;  // set when the file is a `brdfkit fit` JSON
  std::string material;             // set when the file is a published-fits file
};

// Reads a parameter file of either kind, told apart by its content (a published-fits file has
// a `materials` object). `material` must be empty for a fit JSON and name one material of a
// published-fits file; InputError otherwise, naming the file — for an unknown material the
// message lists the closest known names.
LoadedParams load_params(const std::filesystem::path& file, const std::string& material);
Brdf load_params_file(const std::filesystem::path& file, const std::string& material);

// What `eval` and `tabulate` accept: a model name (sums "a+b" included) with `--param`
// arguments, or a parameter file (`--params`, with `--material` for a published-fits file) whose
// values the `--param` arguments then override. Exactly one of `model` and `file` must be given;
// InputError otherwise, naming the options.
Brdf brdf_from_arguments(const std::string& model, const std::vector<std::string>& params,
                         const std::filesystem::path& file, const std::string& material);

}  // namespace brdfkit::fit
