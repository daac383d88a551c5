#include "brdfkit/export/provenance.h"

#include <fmt/format.h>

namespace brdfkit::exporter {

std::vector<std::string> provenance_lines(const Provenance& p) {
  std::vector<std::string> out;
  out.push_back(fmt::format("written by brdfkit {} (export to {}): model {}", p.version, p.target, p.model));
  if (!p.data_file.empty())
    out.push_back(fmt::format("fitted to {} (sha256 {})", p.data_file, p.data_sha256.empty() ? "unknown" : p.data_sha256));
  if (p.source_error)
    out.push_back(fmt::format("fit of {}: {} error {:.6g} against the measurement", p.source_model, p.metric, *p.source_error));
  if (p.refitted)
    out.push_back(fmt::format("refitted from {} into {} on the MERL grid under {}: added error {:.6g}", p.source_model,
                              p.model, p.metric, p.added_error.value_or(0.0)));
  else
    out.push_back(fmt::format("the fit's own model: exported exactly (added error 0)"));
  return out;
}

nlohmann::json provenance_json(const Provenance& p) {
  nlohmann::json j = {{"generator", "brdfkit " + p.version}, {"target", p.target}, {"model", p.model},
                      {"source_model", p.source_model}, {"metric", p.metric}, {"refitted", p.refitted},
                      {"added_error", p.refitted ? nlohmann::json(p.added_error.value_or(0.0)) : nlohmann::json(0.0)}};
  if (!p.data_file.empty()) j["data"] = {{"file", p.data_file}, {"sha256", p.data_sha256}};
  if (p.source_error) j["source_error"] = *p.source_error;
  return j;
}

}  // namespace brdfkit::exporter
