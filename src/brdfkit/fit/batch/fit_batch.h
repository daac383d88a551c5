#pragma once
// `fit-all`: every material × model fitted, saved and summarized, resumable. Each fit is saved
// atomically as OUTDIR/<material>/<model>.json the moment it ends, so a killed batch loses at
// most the fits in flight; a rerun keeps every saved fit whose data SHA-256, model, version and
// options match (fit_job_matches) and refits the rest. A failed fit (unreadable file, data the
// metric cannot answer, solver failure) becomes a row with its reason; the batch goes on.
//
// Several batches may share OUTDIR at once (two `fit-all`, a Python batch, threads of one
// process); none corrupts or repeats another's fit. The protocol (claims: fit_claim.h):
//  1. A fit is claimed first: flock(LOCK_EX | LOCK_NB) on OUTDIR/.claims/fits/<material>/<model>.lock,
//     held while the fit is checked, run and saved. A claim held elsewhere is skipped and tried
//     once more after the batch's other fits; still held then, the row is "running elsewhere".
//     The kernel drops a claim when its holder dies (even by SIGKILL): no claim goes stale.
//  2. Holding the claim: the temporaries of <model>.json (a writer killed mid-write: nobody else
//     can be writing it) are removed, a saved result that matches is kept ("resumed"), else the
//     fit runs and its JSON is written to a temporary in the same folder and renamed into place.
//  3. summary.csv and table.txt are written last, atomically, under OUTDIR/.claims/summary.lock
//     (waited for): each fit this batch did not save is read again from disk first, so the
//     batch that finishes last lists every fit of its inputs × models exactly once, with the
//     results the others saved.
// The lock files stay in OUTDIR/.claims (empty files; removing one would race with its next holder).
//
// Stopping: when *stop becomes true (the CLI sets it on Ctrl-C) no further fit starts; fits in
// flight finish and are saved (a fit cannot be abandoned halfway); the rest are "unfinished", and
// the summary is written. An output that cannot be written (OutputError: full disk, file size
// limit) stops the batch the same way but writes no summary: run_fit_batch rethrows it.
#include <atomic>
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
// settings, InputError for an unreadable compare file (before any fit starts), OutputError for a
// result or summary that cannot be written. `stop` (may be null) is read between fits.
BatchSummary run_fit_batch(const std::vector<BatchInput>& inputs, const std::vector<const Model*>& models,
                           const std::filesystem::path& out_dir, const BatchSettings& settings,
                           const BatchLog& log = {}, const std::atomic<bool>* stop = nullptr);

// A batch spread over processes or machines (Python's brdfkit.batch on a Dask cluster) is these
// two steps. run_batch_fit is one task: one fit under the claim protocol above, in any process
// that sees OUTDIR, returning the row run_fit_batch would list for it (a claim held elsewhere:
// FitStatus::Elsewhere; the caller runs the task once more at the end, as run_fit_batch does).
// `settings.compare` and `jobs` are the summary's and the caller's. OutputError as above.
BatchRow run_batch_fit(const BatchInput& input, const Model& model, const std::filesystem::path& out_dir,
                       const BatchSettings& settings);
// summarize_batch then writes summary.csv and table.txt from every task's row, material-major in
// the order of inputs × models (a task never run: FitStatus::Unfinished with its reason), exactly
// as run_fit_batch writes them: rows not saved by their task are read again from disk, the
// published fits of `compare` evaluated. `interrupted`: the batch was stopped before its end;
// `seconds`: how long its tasks took (wall time), for the summary and the log.
BatchSummary summarize_batch(const std::vector<BatchInput>& inputs, const std::vector<const Model*>& models,
                             const std::filesystem::path& out_dir, const BatchSettings& settings,
                             std::vector<BatchRow> rows, bool interrupted, double seconds, const BatchLog& log = {});

// The line a batch logs for a finished fit: "[done/total] material model: <status and value>".
std::string batch_progress_line(const BatchRow& row, const std::string& fit_metric, size_t done, size_t total);

}  // namespace brdfkit::fit
