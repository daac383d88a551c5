#include "brdfkit/fit/batch/batch_summary.h"

#include <fmt/format.h>

#include <algorithm>

#include "brdfkit/fit/metric/metric.h"

namespace brdfkit::fit {

std::string_view status_name(FitStatus s) {
  switch (s) {
    case FitStatus::Fitted: return "fitted";
    case FitStatus::Resumed: return "resumed";
    case FitStatus::Failed: return "failed";
    case FitStatus::Elsewhere: return "running elsewhere";
    case FitStatus::Unfinished: return "unfinished";
  }
  return "failed";
}

std::optional<double> BatchRow::metric(const std::string& id) const {
  for (const auto& [k, v] : metrics)
    if (k == id) return v;
  return std::nullopt;
}

size_t BatchSummary::count(FitStatus s) const {
  return size_t(std::count_if(rows.begin(), rows.end(), [&](const BatchRow& r) { return r.status == s; }));
}

namespace {

// RFC 4180: quote fields holding a separator, a quote or a line break.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string number(std::optional<double> v) { return v ? fmt::format("{}", *v) : ""; }

bool saved(const BatchRow& r) { return r.status == FitStatus::Fitted || r.status == FitStatus::Resumed; }

// The table's cell of a fit that has no value.
std::string unsaved_cell(FitStatus s) { return s == FitStatus::Elsewhere ? "running" : std::string(status_name(s)); }

// Below the table: each fit without a result, by status, with its reason.
std::string unsaved_notes(const BatchSummary& s) {
  std::string out;
  const std::pair<FitStatus, const char*> sections[] = {
      {FitStatus::Failed, "failed fits:"},
      {FitStatus::Elsewhere, "running in another process (its results will be saved in this folder):"},
      {FitStatus::Unfinished, "unfinished fits (a rerun fits them):"}};
  for (const auto& [status, title] : sections) {
    if (s.count(status) == 0) continue;
    out += std::string(title) + "\n";
    for (const BatchRow& r : s.rows)
      if (r.status == status)
        out += r.reason.empty() ? fmt::format("  {} / {}\n", r.material, r.model)
                                : fmt::format("  {} / {}: {}\n", r.material, r.model, r.reason);
  }
  return out;
}

std::optional<double> published_of(const BatchSummary& s, const std::string& material) {
  for (size_t i = 0; i < s.materials.size() && i < s.published.size(); ++i)
    if (s.materials[i] == material) return s.published[i];
  return std::nullopt;
}

}  // namespace

std::string summary_csv(const BatchSummary& s) {
  const bool compare = !s.published_file.empty();
  std::string out = "material,model,procedure,fit_metric,status";
  for (auto id : metric_ids()) out.append(",").append(id);
  if (compare) out.append(",published_").append(s.fit_metric);
  out += ",seconds,iterations,converged,reason\n";
  for (const BatchRow& r : s.rows) {
    out += fmt::format("{},{},{},{},{}", csv_field(r.material), csv_field(r.model), csv_field(s.procedure),
                       s.fit_metric, status_name(r.status));
    for (auto id : metric_ids()) out.append(",").append(number(r.metric(std::string(id))));
    if (compare) out.append(",").append(number(published_of(s, r.material)));
    const bool ok = saved(r);
    out += fmt::format(",{},{},{},{}\n", ok ? fmt::format("{:.3f}", r.seconds) : "", ok ? std::to_string(r.iterations) : "",
                       ok ? (r.converged ? "yes" : "no") : "", csv_field(r.reason));
  }
  return out;
}

std::string summary_table(const BatchSummary& s) {
  auto cell = [&](const std::string& material, const std::string& model) -> std::string {
    for (const BatchRow& r : s.rows)
      if (r.material == material && r.model == model) {
        if (!saved(r)) return unsaved_cell(r.status);
        const auto v = r.metric(s.fit_metric);
        return v ? fmt::format("{:.4g}", *v) : "n/a";
      }
    return "";
  };
  const bool compare = !s.published_file.empty();
  const std::string published_label = "published";
  size_t first = std::string("model").size();
  for (const auto& m : s.models) first = std::max(first, m.size());
  if (compare) first = std::max(first, published_label.size());
  std::vector<size_t> width;
  for (const auto& m : s.materials) width.push_back(std::max<size_t>(m.size(), 10));
  std::string out = fmt::format("{} error of each fit ({}{}):\n", s.fit_metric,
                                s.procedure.empty() ? "plain fit under " + s.fit_metric : "procedure " + s.procedure,
                                compare ? "; last row: the published fits of " + s.published_file : "");
  out += fmt::format("{:<{}}", "model", first);
  for (size_t j = 0; j < s.materials.size(); ++j) out += fmt::format("  {:>{}}", s.materials[j], width[j]);
  out += "\n";
  for (const auto& model : s.models) {
    out += fmt::format("{:<{}}", model, first);
    for (size_t j = 0; j < s.materials.size(); ++j) out += fmt::format("  {:>{}}", cell(s.materials[j], model), width[j]);
    out += "\n";
  }
  if (compare) {
    out += fmt::format("{:<{}}", published_label, first);
    for (size_t j = 0; j < s.materials.size(); ++j) {
      const auto v = j < s.published.size() ? s.published[j] : std::nullopt;
      out += fmt::format("  {:>{}}", v ? fmt::format("{:.4g}", *v) : "-", width[j]);
    }
    out += "\n";
  }
  return out + unsaved_notes(s);
}

nlohmann::json summary_json(const BatchSummary& s) {
  nlohmann::json rows = nlohmann::json::array();
  for (const BatchRow& r : s.rows) {
    nlohmann::json metrics = nlohmann::json::object();
    for (const auto& [id, v] : r.metrics) metrics[id] = v ? nlohmann::json(*v) : nlohmann::json(nullptr);
    nlohmann::json row = {{"material", r.material}, {"model", r.model},     {"status", status_name(r.status)},
                          {"metrics", metrics},     {"seconds", r.seconds}, {"iterations", r.iterations},
                          {"converged", r.converged}};
    if (!r.json.empty()) row["json"] = r.json;
    if (!r.reason.empty()) row["reason"] = r.reason;
    if (!s.published_file.empty()) {
      const auto p = published_of(s, r.material);
      row["published"] = p ? nlohmann::json(*p) : nlohmann::json(nullptr);
    }
    rows.push_back(row);
  }
  return {{"procedure", s.procedure.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.procedure)},
          {"fit_metric", s.fit_metric},
          {"materials", s.materials},
          {"models", s.models},
          {"fitted", s.count(FitStatus::Fitted)},
          {"resumed", s.count(FitStatus::Resumed)},
          {"failed", s.count(FitStatus::Failed)},
          {"running_elsewhere", s.count(FitStatus::Elsewhere)},
          {"unfinished", s.count(FitStatus::Unfinished)},
          {"interrupted", s.interrupted},
          {"wall_seconds", s.wall_seconds},
          {"published_file", s.published_file},
          {"rows", rows}};
}

}  // namespace brdfkit::fit
