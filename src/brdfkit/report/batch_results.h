#pragma once
// A `fit-all` output folder read back for the report: OUTDIR/<material>/<model>.json (fit/batch)
// as fits with their parameters and metrics, and the measured file each was fitted to.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdfkit/models/model.h"

namespace brdfkit::report {

struct FitResult {
  std::string model;
  std::filesystem::path json;   // the fit's file
  nlohmann::json record;        // its content
  Brdf brdf;
  std::optional<double> metric(const std::string& id) const;
};

struct MaterialResult {
  std::string name;
  std::filesystem::path data_file;  // empty when it cannot be found any more
  std::vector<FitResult> fits;      // sorted by the fitting metric, best first (failed ones last)
};

struct BatchResults {
  std::filesystem::path dir;
  std::string fit_metric;
  std::vector<std::string> metrics;  // every metric id found, the fitting metric first
  std::vector<std::string> models;   // every model found, in catalogue order
  std::vector<MaterialResult> materials;  // sorted by name
};

// InputError when `dir` holds no fit. A fit JSON that does not load is an InputError naming it.
// The data file named in a fit is looked for as written, then relative to `dir` and its parent.
BatchResults load_batch_results(const std::filesystem::path& dir);

}  // namespace brdfkit::report
