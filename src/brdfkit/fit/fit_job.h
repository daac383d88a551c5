#pragma once
// One material × one model → a saved fit: what `fit` does once and `fit-all` does for every
// pair. The settings name either a procedure of DESIGN.md §8 (whose metric is the fitting metric)
// or a plain fit under a metric; the saved JSON (fit_record.h, DESIGN.md §1) also carries every
// setting the result depends on, so a batch can tell whether a saved fit answers the same question.
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdfkit/fit/fit_record.h"
#include "brdfkit/fit/metric/metric_store.h"
#include "brdfkit/fit/procedure/procedure.h"
#include "brdfkit/fit/settings/fit_settings.h"
#include "brdfkit/models/model.h"

namespace brdfkit::fit {

struct FitJobResult {
  FitRecord record;                // metrics left empty: the caller reports what it wants
  FitResult fit;                   // solver details (best start …)
  std::vector<std::string> steps;  // what the procedure did, one line each
};

// Fits `model` to the store's data (read from `file`, whose SHA-256 is `sha256`). Throws
// SettingError (bad settings), InputError (a file name that is not UTF-8, data the metric cannot
// answer, incompatible model) or FitError (no finite start).
FitJobResult run_fit_job(const Model& model, MetricStore& store, const std::string& file, const std::string& sha256,
                         const FitSettings& settings, const Progress& progress = {});

// run_fit_job, then the metrics `report` (ids) on the same store and grids: what `brdfkit fit`
// and Python's brdfkit.fit return, so both give the same numbers.
FitJobResult fit_and_report(const Model& model, MetricStore& store, const std::string& file, const std::string& sha256,
                            const FitSettings& settings, const std::vector<std::string>& report,
                            const Progress& progress = {});

// The record's JSON plus the job's options (fit.procedure — null for a plain fit —,
// fit.per_channel_shape, fit.max_iterations, fit.best_start, fit.start_scan_points, fit.steps) and,
// when given, the material name (data.material).
nlohmann::json fit_job_json(const FitJobResult& r, const FitSettings& settings, const std::string& material = "");

// True when `saved` (a fit_job_json document) is the fit of `model` on the data with this
// SHA-256 under these settings, by this brdfkit version, with a finite value for every parameter
// and an entry (number or null with a note) for every metric of `report`.
bool fit_job_matches(const nlohmann::json& saved, const std::string& model, const std::string& sha256,
                     const FitSettings& settings, const std::vector<std::string>& report);

}  // namespace brdfkit::fit
