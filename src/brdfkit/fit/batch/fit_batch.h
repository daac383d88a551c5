#pragma once
// `fit-all`: every material × model fitted, saved and summarized, resumable. Each fit is saved
// atomically as OUTDIR/<material>/<model>.json the moment it ends, so a killed batch loses at
// most the fits in flight; a rerun keeps every saved fit whose data SHA-256, model, version and
// options match (fit_job_matches) and refits the rest. A failed fit (unreadable file, data the
// metric cannot answer, solver failure) becomes a row with its reason; the batch goes on.
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "brdfkit/fit/batch/batch_summary.h"
#include "brdfkit/fit/fit_job.h"
#include "brdfkit/models/model.h"

namespace brdfkit::fit {

struct BatchInput {
  std::string material;  // the file's stem: MERL files are named after their material
  std::filesystem::path file;
};

// Arguments → inputs: a folder gives every file with a measured extension (load.h) in it, sorted
// by name; a file is taken as given (one that cannot be read fails its fits, not the batch).
// InputError, before anything is written, for an input that does not exist, a file name that is
// not UTF-8 (the fits' JSON holds it), no file left, or two inputs that share a material name.
std::vector<BatchInput> list_batch_inputs(const std::vector<std::string>& args);

// The settings of a batch: the one type `fit-all`, and the Python batch read.
struct BatchSettings {
  FitSettings fit;                  // every fit's settings
  std::vector<std::string> report;  // metrics in every row and JSON; the fitting metric is added first
  int jobs = 1;                     // fits run at once (each fit is itself parallel)
  std::string compare;              // a published-fits file (DESIGN.md §10), or empty

  static constexpr int kMaxJobs = 256;
  // SettingError naming the first bad setting (the fit's, an unknown report metric, jobs).
  void validate() const;
};

// One line per finished fit, and the final count.
using BatchLog = std::function<void(std::string_view)>;

// Runs the batch into `out_dir` and writes summary.csv and table.txt there. SettingError for bad
// settings, InputError for an unreadable compare file (before any fit starts).
BatchSummary run_fit_batch(const std::vector<BatchInput>& inputs, const std::vector<const Model*>& models,
                           const std::filesystem::path& out_dir, const BatchSettings& settings,
                           const BatchLog& log = {});

}  // namespace brdfkit::fit
