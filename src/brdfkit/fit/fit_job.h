#pragma once
// One material × one model → a saved fit: what `fit` does once and `fit-all` does for every
// pair. The options name either a procedure of DESIGN.md §8 (whose metric is the fitting metric)
// or a plain fit under a metric; the saved JSON (fit_record.h, DESIGN.md §1) also carries every
// option the result depends on, so a batch can tell whether a saved fit answers the same question.
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdfkit/fit/fit_record.h"
#include "brdfkit/fit/engine/variable_projection.h"
#include "brdfkit/measured/measured_brdf.h"
#include "brdfkit/models/model.h"

namespace brdfkit::fit {

struct FitJobOptions {
  std::string procedure;  // empty: a plain fit under `metric`
  std::string metric;     // plain fit: its metric (empty = ngan); with a procedure: an override
  bool per_channel_shape = false;
  int starts = 1;
  std::uint64_t seed = 1;
  int max_iterations = 100;
  int coarsen = 1;
  std::function<void(std::string_view)> progress;  // the procedure's one-line step messages
};

// InputError naming the option: unknown procedure or metric, starts/coarsen/max-iterations < 1.
void validate(const FitJobOptions& opt);
// The metric the fit minimizes: the override, else the procedure's, else ngan.
std::string fitting_metric(const FitJobOptions& opt);

struct FitJobResult {
  FitRecord record;                // metrics left empty: the caller reports what it wants
  FitResult fit;                   // solver details (best start …)
  std::vector<std::string> steps;  // what the procedure did, one line each
};

// Fits `model` to `data` (read from `file`, whose SHA-256 is `sha256`). Throws InputError (bad
// options, data the metric cannot answer, incompatible model) or FitError (no finite start).
FitJobResult run_fit_job(const Model& model, const MeasuredBrdf& data, const std::string& file,
                         const std::string& sha256, const FitJobOptions& opt);

// The record's JSON plus the job's options (fit.procedure — null for a plain fit —,
// fit.per_channel_shape, fit.max_iterations, fit.best_start, fit.start_scan_points, fit.steps) and,
// when given, the material name (data.material).
nlohmann::json fit_job_json(const FitJobResult& r, const FitJobOptions& opt, const std::string& material = "");

// True when `saved` (a fit_job_json document) is the fit of `model` on the data with this
// SHA-256 under these options, by this brdfkit version, with a finite value for every parameter
// and an entry (number or null with a note) for every metric of `report`.
bool fit_job_matches(const nlohmann::json& saved, const std::string& model, const std::string& sha256,
                     const FitJobOptions& opt, const std::vector<std::string>& report);

}  // namespace brdfkit::fit
