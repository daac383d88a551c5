// `brdfkit models [NAME ...] [--json]`: every model of the catalogue (or the named ones, sums
// "a+b" of models/lobe_sum.h included) with its parameter table.
#include <cmath>

#include <fmt/format.h>

#include <iostream>
#include <nlohmann/json.hpp>

#include "brdfkit/core/json_text.h"
#include "brdfkit/models/model_json.h"
#include "brdfkit/models/model.h"
#include "command.h"

namespace brdfkit::cli {
namespace {

// ", formula on [a, b]" where the formula's domain is wider than the fitter's box.
std::string domain_note(const ParamSpec& p) {
  if (p.valid_lower() == p.lower && p.valid_upper() == p.upper) return "";
  const double hi = p.valid_upper();
  return fmt::format(", formula on [{:g}, {}", p.valid_lower(), std::isfinite(hi) ? fmt::format("{:g}]", hi) : "inf)");
}

std::vector<const Model*> selected(const std::vector<std::string>& names) {
  if (names.empty()) return {all_models().begin(), all_models().end()};
  std::vector<const Model*> out;
  for (const auto& n : names) out.push_back(&model_by_name(n));
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
  auto names = std::make_shared<std::vector<std::string>>();
  sub->add_option("NAME", *names,
                  "Models to show (default: the whole catalogue); a sum of models joined by '+' "
                  "(e.g. cook-torrance-beckmann+cook-torrance-beckmann) shows its prefixed parameters");
  sub->add_flag("--json", *json, "Print JSON instead of a table");
  return [json, names]() {
    const std::vector<const Model*> models = selected(*names);
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
