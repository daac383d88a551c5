#include "brdfkit/models/model_json.h"

#include <cmath>

namespace brdfkit {

namespace {
// JSON has no ∞: an unbounded domain edge is null.
nlohmann::json finite_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }
}  // namespace

nlohmann::json model_json(const Model& m) {
  nlohmann::json params = nlohmann::json::array();
  for (const auto& p : m.params())
    params.push_back({{"name", p.name},
                      {"lower", p.lower},
                      {"upper", p.upper},
                      {"domain", {finite_or_null(p.valid_lower()), finite_or_null(p.valid_upper())}},
                      {"default", p.def},
                      {"scope", p.scope == Scope::PerChannel ? "per-channel" : "shared"},
                      {"linear", p.linear},
                      {"doc", p.doc}});
  return {{"name", m.name()}, {"description", m.description()}, {"reciprocal", m.reciprocal()}, {"params", params}};
}

}  // namespace brdfkit
