#pragma once
// Where an exported material comes from, written into every exported file (glTF extras, comments
// of the XML, pbrt, .brdf and GLSL files) and printed by `brdfkit export`: the fit's model, data
// and metric, and for a refitted export the error the refit adds (export/refit.h).
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace brdfkit::exporter {

struct Provenance {
  std::string target;        // the format written
  std::string model;         // the model written
  std::string source_model;  // the fit's model (= model unless refitted)
  std::string data_file, data_sha256;
  std::string metric;                  // the fit's metric (the refit's too)
  std::optional<double> source_error;  // the fit's own error under `metric`, when its JSON has it
  bool refitted = false;
  std::optional<double> added_error;   // refitted: the written model's error against the source fit
  std::string version = BRDFKIT_VERSION;
};

// One sentence per line, without comment markers.
std::vector<std::string> provenance_lines(const Provenance& p);
nlohmann::json provenance_json(const Provenance& p);

}  // namespace brdfkit::exporter
