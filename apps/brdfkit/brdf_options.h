#pragma once
// The options that name a BRDF on the command line, shared by `eval` and `tabulate`: a model with
// --param values, or a saved fit / published-fits file (--params, --material) that --param overrides.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "brdfkit/fit/param_source.h"

namespace brdfkit::cli {

struct BrdfOptions {
  std::string model, params_file, material;
  std::vector<std::string> params;

  Brdf brdf() const { return fit::brdf_from_arguments(model, params, params_file, material); }
};

inline void add_brdf_options(CLI::App* sub, BrdfOptions& o) {
  sub->add_option("model", o.model, "Model name (see `brdfkit models`; sums such as a+b allowed)");
  sub->add_option("--param", o.params,
                  "name=value (all channels), name[r|g|b]=value (one channel) or name=r,g,b; repeatable; overrides "
                  "the values of --params");
  sub->add_option("--params,-p", o.params_file, "A fit saved by `brdfkit fit`, or a published-fits file");
  sub->add_option("--material", o.material, "The material of a published-fits file");
}

}  // namespace brdfkit::cli
