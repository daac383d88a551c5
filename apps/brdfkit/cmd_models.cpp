// `brdfkit models [--json]`: every model of the catalogue with its parameter table.
#include <fmt/format.h>

#include <iostream>
#include <nlohmann/json.hpp>

#include "brdfkit/models/model.h"
#include "command.h"

namespace brdfkit::cli {
namespace {

nlohmann::json models_json() {
  nlohmann::json out = nlohmann::json::array();
  for (const Model* m : all_models()) {
    nlohmann::json params = nlohmann::json::array();
    for (const auto& p : m->params())
      params.push_back({{"name", p.name},
                        {"lower", p.lower},
                        {"upper", p.upper},
                        {"default", p.def},
                        {"scope", p.scope == Scope::PerChannel ? "per-channel" : "shared"},
                        {"linear", p.linear},
                        {"doc", p.doc}});
    out.push_back({{"name", m->name()}, {"description", m->description()}, {"reciprocal", m->reciprocal()},
                   {"params", params}});
  }
  return out;
}

const CommandRegistration reg("models", [](CLI::App& app) {
  auto* sub = app.add_subcommand("models", "List every model with its parameters, bounds and defaults");
  auto json = std::make_shared<bool>(false);
  sub->add_flag("--json", *json, "Print JSON instead of a table");
  return [json]() {
    if (*json) {
      std::cout << models_json().dump(2) << "\n";
      return 0;
    }
    for (const Model* m : all_models()) {
      std::cout << fmt::format("{}  —  {}\n", m->name(), m->description());
      for (const auto& p : m->params())
        std::cout << fmt::format("    {:<10} [{:g}, {:g}] default {:g}  {}{}  {}\n", p.name, p.lower, p.upper, p.def,
                                 p.scope == Scope::PerChannel ? "per-channel" : "shared", p.linear ? ", linear" : "",
                                 p.doc);
    }
    return 0;
  };
});

}  // namespace
}  // namespace brdfkit::cli
