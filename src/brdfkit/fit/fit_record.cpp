#include "brdfkit/fit/fit_record.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>

#include "brdfkit/core/atomic_file.h"
#include "brdfkit/core/error.h"
#include "brdfkit/core/json_text.h"

namespace brdfkit::fit {

bool shape_differs_by_channel(const Model& model, const ParamValues& values) {
  const ParamTable& table = model.params();
  for (size_t i = 0; i < table.size(); ++i)
    if (table[i].scope == Scope::Shared &&
        !(values.values[0][i] == values.values[1][i] && values.values[0][i] == values.values[2][i]))
      return true;
  return false;
}

nlohmann::json to_json(const FitRecord& r) {
  const Model& model = model_by_name(r.model);
  nlohmann::json params = nlohmann::json::array();
  const ParamTable& table = model.params();
  const bool per_channel = r.per_channel_shape || shape_differs_by_channel(model, r.values);
  for (size_t i = 0; i < table.size(); ++i)
    params.push_back({{"name", table[i].name},
                      {"scope", table[i].scope == Scope::PerChannel || per_channel ? "per-channel" : "shared"},
                      {"values", {r.values.values[0][i], r.values.values[1][i], r.values.values[2][i]}}});
  nlohmann::json metrics = nlohmann::json::object();
  for (const MetricReport& m : r.metrics) {
    if (m.value) metrics[m.id] = *m.value;
    else metrics[m.id] = nullptr;
  }
  nlohmann::json notes = nlohmann::json::object();
  for (const MetricReport& m : r.metrics)
    if (!m.note.empty()) notes[m.id] = m.note;
  return {{"format", "brdfkit-fit"},
          {"brdfkit_version", r.version},
          {"model", r.model},
          {"shape", per_channel ? "per-channel" : "shared"},
          {"params", params},
          {"data", {{"file", r.data_file}, {"sha256", r.data_sha256}}},
          {"fit",
           {{"metric", r.fit_metric},
            {"starts", r.starts},
            {"seed", r.seed},
            {"iterations", r.iterations},
            {"seconds", r.seconds},
            {"converged", r.converged},
            {"message", r.message}}},
          {"grid_coarsen", r.coarsen},
          {"metrics", metrics},
          {"metric_notes", notes}};
}

namespace {

const nlohmann::json& field(const nlohmann::json& j, const char* name, const std::string& where) {
  if (!j.is_object() || !j.contains(name)) throw InputError(where, std::string("missing field '") + name + "'");
  return j.at(name);
}

std::string string_field(const nlohmann::json& j, const char* name, const std::string& where) {
  const auto& v = field(j, name, where);
  if (!v.is_string()) throw InputError(where, std::string("field '") + name + "' must be a string");
  return v.get<std::string>();
}

double number_field(const nlohmann::json& v, const std::string& where) {
  if (!v.is_number()) throw InputError(where, "must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw InputError(where, "must be finite");
  return x;
}

// "shape" or, in files written before per-channel shapes were saved, fit.per_channel_shape.
bool per_channel_shape_of(const nlohmann::json& j, const std::string& where) {
  if (j.contains("shape")) {
    const std::string shape = string_field(j, "shape", where);
    if (shape != "shared" && shape != "per-channel")
      throw InputError(where + ": field 'shape'", "must be \"shared\" or \"per-channel\", not \"" + shape + "\"");
    return shape == "per-channel";
  }
  return j.contains("fit") && j["fit"].is_object() && j["fit"].contains("per_channel_shape") &&
         j["fit"]["per_channel_shape"].is_boolean() && j["fit"]["per_channel_shape"].get<bool>();
}

// The "params" array: every parameter of the model once, three values within its bounds, equal
// across channels for a shared parameter unless the fit has one shape per channel.
void read_params(const nlohmann::json& j, const std::string& where, FitRecord& r) {
  const ParamTable& table = model_by_name(r.model).params();
  r.values = ParamValues::defaults(table);
  const auto& params = field(j, "params", where);
  if (!params.is_array()) throw InputError(where + ": field 'params'", "must be an array");
  std::vector<bool> seen(table.size(), false);
  for (size_t k = 0; k < params.size(); ++k) {
    const std::string at = where + ": params[" + std::to_string(k) + "]";
    const std::string name = string_field(params[k], "name", at);
    const int i = find_param(table, name);
    if (i < 0) throw InputError(at, "parameter '" + name + "' is not a parameter of model '" + r.model + "'");
    const auto& values = field(params[k], "values", at);
    if (!values.is_array() || values.size() != 3) throw InputError(at + ".values", "must be an array of 3 numbers (R, G, B)");
    const ParamSpec& s = table[size_t(i)];
    for (int c = 0; c < 3; ++c) {
      const double x = number_field(values[size_t(c)], at + ".values[" + std::to_string(c) + "]");
      if (!s.in_domain(x))
        throw InputError(at + ".values[" + std::to_string(c) + "]",
                         fmt::format("{} = {} outside the formula's domain [{}, {}]", name, x, s.valid_lower(),
                                     s.valid_upper()));
      r.values.values[size_t(c)][size_t(i)] = x;
    }
    if (s.scope == Scope::Shared && !r.per_channel_shape &&
        !(r.values.values[0][size_t(i)] == r.values.values[1][size_t(i)] &&
          r.values.values[0][size_t(i)] == r.values.values[2][size_t(i)]))
      throw InputError(at, "parameter '" + name +
                               "' is shared by the three channels but its values differ (a fit with one shape per "
                               "channel says \"shape\": \"per-channel\")");
    seen[size_t(i)] = true;
  }
  for (size_t i = 0; i < table.size(); ++i)
    if (!seen[i]) throw InputError(where + ": field 'params'", "parameter '" + table[i].name + "' is missing");
}

// What the fit was made from and how: data file and digest, metric, grid coarsening, metrics.
void read_provenance(const nlohmann::json& j, const std::string& where, FitRecord& r) {
  if (j.contains("data") && j["data"].is_object()) {
    const auto& d = j["data"];
    if (d.contains("file") && d["file"].is_string()) r.data_file = d["file"].get<std::string>();
    if (d.contains("sha256") && d["sha256"].is_string()) r.data_sha256 = d["sha256"].get<std::string>();
  }
  if (j.contains("fit") && j["fit"].is_object()) {
    const auto& f = j["fit"];
    if (f.contains("metric") && f["metric"].is_string()) r.fit_metric = f["metric"].get<std::string>();
  }
  if (j.contains("grid_coarsen")) {
    const auto& g = j["grid_coarsen"];
    // Read at full width: get<int>() would wrap 4294967297 to 1 and accept it.
    const std::int64_t coarsen = g.is_number_integer() ? g.get<std::int64_t>() : 0;
    if (coarsen < 1 || coarsen > std::numeric_limits<int>::max())
      throw InputError(where + ": field 'grid_coarsen'", fmt::format("must be an integer in [1, {}]", std::numeric_limits<int>::max()));
    r.coarsen = int(coarsen);
  }
  if (j.contains("metrics") && j["metrics"].is_object())
    for (const auto& it : j["metrics"].items())
      r.metrics.push_back(
          {it.key(), it.value().is_number() ? std::optional<double>(it.value().get<double>()) : std::nullopt, ""});
}

}  // namespace

FitRecord fit_record_from_json(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) throw InputError(where, "not a JSON object");
  FitRecord r;
  r.model = string_field(j, "model", where);
  try {
    model_by_name(r.model);
  } catch (const InputError& e) {
    throw InputError(where + ": field 'model'", e.what());
  }
  r.version = j.contains("brdfkit_version") && j["brdfkit_version"].is_string() ? j["brdfkit_version"].get<std::string>() : "";
  r.per_channel_shape = per_channel_shape_of(j, where);
  read_params(j, where, r);
  read_provenance(j, where, r);
  return r;
}

void save_fit_record(const std::filesystem::path& file, const FitRecord& r) {
  write_file_atomically(file, json_text(to_json(r)) + "\n");
}

FitRecord load_fit_record(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in || std::filesystem::is_directory(file)) throw InputError(file.string(), "cannot open for reading");
  nlohmann::json j;
  try {
    in >> j;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string(), std::string("not valid JSON: ") + e.what());
  }
  return fit_record_from_json(j, file.string());
}

std::string format_params(const Model& model, const ParamValues& values) {
  std::string out;
  const ParamTable& table = model.params();
  for (size_t i = 0; i < table.size(); ++i) {
    const bool one = values.values[0][i] == values.values[1][i] && values.values[0][i] == values.values[2][i];
    if (table[i].scope == Scope::Shared && one)
      out += fmt::format("  {:<10} {:.9g}\n", table[i].name, values.values[0][i]);
    else
      out += fmt::format("  {:<10} {:.9g} {:.9g} {:.9g}\n", table[i].name, values.values[0][i], values.values[1][i],
                         values.values[2][i]);
  }
  return out;
}

std::string format_metrics(const std::vector<MetricReport>& metrics) {
  std::string out;
  for (const MetricReport& m : metrics) {
    if (m.value) out += fmt::format("  {:<10} {:.9g}\n", m.id, *m.value);
    else out += fmt::format("  {:<10} n/a ({})\n", m.id, m.note);
  }
  return out;
}

}  // namespace brdfkit::fit
