#include "brdfkit/models/model_json.h"

namespace brdfkit {

nlohmann::json model_json(const Model& m) {
  nlohmann::json params = nlohmann::json::array();
  for (const auto& p : m.params())
    params.push_back({{"name", p.name},
                      {"lower", p.lower},
                      {"upper", p.upper},
                      {"default", p.def},
                      {"scope", p.scope == Scope::PerChannel ? "per-channel" : "shared"},
                      {"linear", p.linear},
                      {"doc", p.doc}});
  return {{"name", m.name()}, {"description", m.description()}, {"reciprocal", m.reciprocal()}, {"params", params}};
}

}  // namespace brdfkit
