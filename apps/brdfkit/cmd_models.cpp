// `brdfkit models [NAME ...] [--json | --names]`: every model of the catalogue (or the named ones:
// sums "a+b" of models/lobe_sum.h, and fit-all's sets of models/model_sets.h) with its parameter
// table, or its name alone for scripts.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <iostream>
#include <nlohmann/json.hpp>

#include "brdfkit/core/json_text.h"
#include "brdfkit/models/model_json.h"
#include "brdfkit/models/model.h"
#include "brdfkit/models/model_sets.h"
#include "command.h"

namespace brdfkit::cli {
namespace {

// ", formula on [a, b]" where the formula's domain is wider than the fitter's box.
std::string domain_note(const ParamSpec& p) {
  if (p.valid_lower() == p.lower && p.valid_upper() == p.upper) return "";
  const double hi = p.valid_upper();
  return fmt::format(", formula on [{:g}, {}", p.valid_lower(), std::isfinite(hi) ? fmt::format("{:g}]", hi) : "inf)");
}

bool is_set_name(const std::string& name) {
  return name == "all" || name == "single-lobe" || name == "renderer" || name == "anisotropic";
}

// The named models in the given order, each once.
std::vector<const Model*> selected(const std::vector<std::string>& names) {
  if (names.empty()) return {all_models().begin(), all_models().end()};
  std::vector<const Model*> out;
  auto add = [&](const Model* m) {
    if (std::find(out.begin(), out.end(), m) == out.end()) out.push_back(m);
  };
  for (const auto& n : names) {
    if (!is_set_name(n)) add(&model_by_name(n));
    else
      for (const Model* m : parse_model_set(n)) add(m);
  }
  return out;
}

nlohmann::json models_json(const std::vector<const Model*>& models) {
  nlohmann::json out = nlohmann::json::array();
  for (const Model* m : models) out.push_back(model_json(*m));
  return out;
}

const CommandRegistration reg("models", [](CLI::App& app) {
  auto* sub = app.add_subcommand("models", "List every model with its parameters, bounds and defaults");
  auto json = std::make_shared<bool>(false);
  auto names_only = std::make_shared<bool>(false);
  auto names = std::make_shared<std::vector<std::string>>();
  sub->add_option("NAME", *names,
                  "Models to show (default: the whole catalogue); a sum of models joined by '+' "
                  "(e.g. cook-torrance-beckmann+cook-torrance-beckmann) shows its prefixed parameters; "
                  "'all', 'single-lobe', 'renderer' and 'anisotropic' are fit-all's sets of models");
  auto* json_flag = sub->add_flag("--json", *json, "Print JSON instead of a table");
  sub->add_flag("--names", *names_only, "Print the models' names only, one per line")->excludes(json_flag);
  return [json, names_only, names]() {
    const std::vector<const Model*> models = selected(*names);
    if (*names_only) {
      for (const Model* m : models) std::cout << m->name() << "\n";
      return 0;
    }
    if (*json) {
      std::cout << json_text(models_json(models)) << "\n";
      return 0;
    }
    for (const Model* m : models) {
      std::cout << fmt::format("{}  —  {}\n", m->name(), m->description());
      for (const auto& p : m->params())
        std::cout << fmt::format("    {:<10} [{:g}, {:g}] default {:g}  {}{}{}  {}\n", p.name, p.lower, p.upper, p.def,
                                 p.scope == Scope::PerChannel ? "per-channel" : "shared", p.linear ? ", linear" : "",
                                 domain_note(p), p.doc);
    }
    return 0;
  };
});

}  // namespace
}  // namespace brdfkit::cli
