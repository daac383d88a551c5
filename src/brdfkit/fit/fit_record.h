#pragma once
// A saved fit (DESIGN.md §1): model name, parameter names and per-channel values, the metric values,
// the data file's SHA-256 and the program version. Reading it back must reproduce the numbers:
// doubles are written with round-trip precision.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdfkit/fit/metric/metric_report.h"
#include "brdfkit/models/model.h"

namespace brdfkit::fit {

struct FitRecord {
  std::string model;
  ParamValues values;  // in the model's ParamTable order
  std::string data_file;
  std::string data_sha256;
  std::string version = BRDFKIT_VERSION;
  std::string fit_metric;
  int starts = 1;
  std::uint64_t seed = 1;
  int iterations = 0;
  double seconds = 0;
  bool converged = false;
  std::string message;
  int coarsen = 1;  // grid coarsening the metrics were computed with (1 = the papers' grids)
  // The lobe shape was fitted per channel (`--per-channel-shape`, the bagher procedure): the
  // model's Shared parameters hold one value per channel. to_json also sets it whenever a Shared
  // parameter's values differ, and writes it as "shape": "per-channel" (with every parameter's
  // "scope" per-channel). Reading: "shape", else (files written before it) fit.per_channel_shape,
  // else one shared shape.
  bool per_channel_shape = false;
  std::vector<MetricReport> metrics;
};

nlohmann::json to_json(const FitRecord& r);
// Validates every field against the model's table; InputError naming `where` and the field.
FitRecord fit_record_from_json(const nlohmann::json& j, const std::string& where);

void save_fit_record(const std::filesystem::path& file, const FitRecord& r);
FitRecord load_fit_record(const std::filesystem::path& file);

// Whether a Shared parameter of the model has different values in the three channels.
bool shape_differs_by_channel(const Model& model, const ParamValues& values);

// Human-readable parameter and metric lines, shared by `fit` and `error` so their numbers print
// identically. A Shared parameter prints one value, or three where its channels differ (a
// per-channel shape).
std::string format_params(const Model& model, const ParamValues& values);
std::string format_metrics(const std::vector<MetricReport>& metrics);

}  // namespace brdfkit::fit
