#pragma once
// What `fit-all` reports: one row per material × model, as a CSV file (every metric value with
// round-trip precision) and as a console table of the fitting metric's error (models × materials).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace brdfkit::fit {

// Resumed: a result already saved (by an earlier run or by another process sharing the folder).
// Elsewhere: another process held the fit's claim (fit_batch.h) when the summary was written.
// Unfinished: not fitted, because the batch was interrupted before this fit started, or because
// the process that held its claim stopped without saving it; a rerun fits it.
enum class FitStatus { Fitted, Resumed, Failed, Elsewhere, Unfinished };
// "fitted", "resumed", "failed", "running elsewhere", "unfinished"
std::string_view status_name(FitStatus s);

struct BatchRow {
  std::string material;
  std::string model;
  FitStatus status = FitStatus::Failed;
  std::string reason;  // why it failed or is unfinished (empty otherwise)
  std::string json;    // the saved fit (empty unless fitted or resumed)
  std::vector<std::pair<std::string, std::optional<double>>> metrics;  // reported values, nullopt = n/a
  double seconds = 0;  // the fit's own time (for a resumed fit, the time it took when it was made)
  int iterations = 0;
  bool converged = false;
  std::optional<double> metric(const std::string& id) const;
};

struct BatchSummary {
  std::string procedure;   // empty: plain fits
  std::string fit_metric;  // the metric the fits minimize: the table's number
  std::vector<std::string> materials;
  std::vector<std::string> models;
  std::vector<BatchRow> rows;  // material-major, models in the order given
  // --compare: the published fit's value under the fitting metric, per material (nullopt when the
  // published file has no such material or the metric cannot be computed).
  std::string published_file;
  std::vector<std::optional<double>> published;  // parallel to `materials` (empty without --compare)
  double wall_seconds = 0;
  bool interrupted = false;  // the batch was asked to stop (fit_batch.h) before its end

  size_t count(FitStatus s) const;
};

// Columns: material, model, procedure, fit_metric, status, one per metric id (metric.h order),
// published_<fit_metric> with --compare, seconds, iterations, converged, reason.
std::string summary_csv(const BatchSummary& s);
// Rows = models, columns = materials; a cell is the fitting metric's value, "failed",
// "running" (elsewhere), "unfinished" (each listed below the table with its reason) or "n/a";
// with --compare a last row gives the published fits' values.
std::string summary_table(const BatchSummary& s);
nlohmann::json summary_json(const BatchSummary& s);

}  // namespace brdfkit::fit
