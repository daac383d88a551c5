#include "brdfkit/fit/batch/fit_batch.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <thread>

#include "brdfkit/core/atomic_file.h"
#include "brdfkit/core/error.h"
#include "brdfkit/core/file_digest.h"
#include "brdfkit/core/free_memory.h"
#include "brdfkit/core/json_text.h"
#include "brdfkit/fit/batch/fit_claim.h"
#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/fit/metric/metric_report.h"
#include "brdfkit/fit/metric/metric_store.h"
#include "brdfkit/fit/procedure/search_box.h"
#include "brdfkit/measured/load.h"
#include "brdfkit/models/published_fits.h"

namespace brdfkit::fit {

namespace fs = std::filesystem;

std::vector<BatchInput> list_batch_inputs(const std::vector<std::string>& args) {
  std::vector<BatchInput> out;
  for (const std::string& a : args) {
    std::error_code ec;
    if (fs::is_directory(a, ec)) {
      std::vector<fs::path> files;
      for (const auto& e : fs::directory_iterator(a, ec))
        if (e.is_regular_file(ec) && has_measured_extension(e.path())) files.push_back(e.path());
      if (ec) throw InputError(a, "cannot list the folder: " + ec.message());
      std::sort(files.begin(), files.end());
      for (const auto& f : files) out.push_back({f.stem().string(), f});
    } else if (!fs::exists(a, ec)) {
      throw InputError(a, ec ? "cannot be read: " + ec.message() : std::string("no such file or folder"));
    } else {
      out.push_back({fs::path(a).stem().string(), fs::path(a)});
    }
  }
  // Every fit's JSON names its file and material: refuse names JSON cannot hold before any fit.
  for (const BatchInput& in : out) require_json_text(in.file.string());
  if (out.empty()) throw InputError("fit-all", "no measured file among the inputs (.binary, .bsdf, .brdf, .alta)");
  std::map<std::string, fs::path> seen;
  for (const BatchInput& in : out) {
    auto [it, fresh] = seen.emplace(in.material, in.file);
    if (!fresh)
      throw InputError(in.file.string(), fmt::format("material name '{}' is also the name of {}: results would "
                                                     "share OUTDIR/{}/; rename one",
                                                     in.material, it->second.string(), in.material));
  }
  return out;
}

std::string batch_progress_line(const BatchRow& row, const std::string& fit_metric, size_t done, size_t total) {
  const std::string what = fmt::format("[{}/{}] {} {}", done, total, row.material, row.model);
  const auto v = row.metric(fit_metric);
  const std::string value = v ? fmt::format("{} {:.5g}", fit_metric, *v) : fit_metric + " n/a";
  switch (row.status) {
    case FitStatus::Failed: return fmt::format("{}: FAILED: {}", what, row.reason);
    case FitStatus::Elsewhere: return what + ": running in another process";
    case FitStatus::Unfinished: return what + ": unfinished: " + row.reason;
    case FitStatus::Resumed: return fmt::format("{}: skipped, already saved ({})", what, value);
    case FitStatus::Fitted: break;
  }
  return fmt::format("{}: {}, {:.1f} s{}", what, value, row.seconds, row.converged ? "" : " (not converged)");
}

namespace {

// One material's data, checksum and report metrics, loaded by the first fit that needs them and
// released when its last fit ends (a full MERL file and its metric grids weigh ~0.5 GB).
struct Material {
  std::mutex mu;
  bool sha_done = false, loaded = false, published_done = false;
  std::string sha, error;
  std::unique_ptr<MeasuredBrdf> data;
  std::unique_ptr<MetricStore> store;  // every fit of the material reuses its domains
  std::map<std::string, std::shared_ptr<const Metric>> metrics;
  std::map<std::string, std::string> undefined;  // metric id → why the data cannot answer it
  std::optional<double> published;
  int remaining = 0;
};

std::optional<nlohmann::json> read_json(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

// Everything shared by the threads of one batch.
class Batch {
 public:
  Batch(const std::vector<BatchInput>& inputs, const std::vector<const Model*>& models, const fs::path& out_dir,
        const BatchSettings& opt, const BatchLog& log, const std::atomic<bool>* stop)
      : inputs_(inputs), models_(models), out_(out_dir), opt_(opt), log_(log), stop_(stop), materials_(inputs.size()) {
    metric_ = fitting_metric(opt.fit);
    report_.push_back(metric_);
    for (const std::string& id : opt.report)
      if (std::find(report_.begin(), report_.end(), id) == report_.end()) report_.push_back(id);
    for (auto& m : materials_) m.remaining = int(models.size());
    if (!opt.compare.empty()) {
      published_.emplace(PublishedFits::read(opt.compare));
      if (!published_->supported()) throw InputError(opt.compare, published_->unsupported_reason());
      const auto names = published_->materials();
      published_names_.insert(names.begin(), names.end());
    }
  }

  BatchSummary run() {
    const auto t0 = std::chrono::steady_clock::now();
    const size_t n = inputs_.size() * models_.size();
    rows_.resize(n);
    std::vector<size_t> all(n);
    for (size_t k = 0; k < n; ++k) {
      all[k] = k;
      rows_[k].material = inputs_[k / models_.size()].material;
      rows_[k].model = std::string(models_[k % models_.size()]->name());
    }
    run_pool(all, false);
    // A fit another process held is tried once more after the others: its holder may have saved
    // it by now (resumed) or died (the claim is free again).
    std::vector<size_t> again;
    for (size_t k = 0; k < n; ++k)
      if (rows_[k].status == FitStatus::Elsewhere) again.push_back(k);
    run_pool(again, true);
    if (output_error_) std::rethrow_exception(output_error_);
    return finish(t0);
  }

  // One fit, as the last try of run(): what a task of a batch spread over processes runs.
  BatchRow run_single(size_t k) {
    rows_.resize(inputs_.size() * models_.size());
    rows_[k].material = inputs_[k / models_.size()].material;
    rows_[k].model = std::string(models_[k % models_.size()]->name());
    run_one(k, true);
    if (output_error_) std::rethrow_exception(output_error_);
    return rows_[k];
  }

  // The summary of rows made elsewhere (run_single in other processes).
  BatchSummary summarize_rows(std::vector<BatchRow> rows, double seconds_before) {
    const auto t0 = std::chrono::steady_clock::now() -
                    std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds_before));
    if (rows.size() != inputs_.size() * models_.size())
      throw SettingError("rows", fmt::format("{} rows for {} materials x {} models", rows.size(), inputs_.size(),
                                             models_.size()));
    rows_ = std::move(rows);
    if (published_)
      for (size_t m = 0; m < inputs_.size(); ++m) compare(inputs_[m], materials_[m]);
    return finish(t0);
  }

 private:
  bool stopping() const { return aborted_ || (stop_ && stop_->load()); }

  BatchSummary finish(std::chrono::steady_clock::time_point t0) {
    BatchSummary s = summarize();
    s.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    log_total(s);
    return s;
  }

  // Runs the fits `ks` on opt_.jobs threads; a fit not started when the batch stops is unfinished.
  void run_pool(const std::vector<size_t>& ks, bool last_try) {
    std::atomic<size_t> next{0};
    auto worker = [&] {
      for (size_t i = next++; i < ks.size(); i = next++) {
        if (!stopping()) {
          run_one(ks[i], last_try);
          continue;
        }
        rows_[ks[i]].status = FitStatus::Unfinished;
        rows_[ks[i]].reason = "the batch was interrupted before this fit started";
      }
    };
    const int threads = std::max(1, std::min<int>(opt_.jobs, int(ks.size())));
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
  }

  void log(const std::string& line) {
    if (!log_) return;
    std::lock_guard lock(log_mu_);
    log_(line);
  }

  void run_one(size_t k, bool last_try) {
    const size_t mi = k / models_.size();
    const BatchInput& in = inputs_[mi];
    const Model& model = *models_[k % models_.size()];
    Material& mat = materials_[mi];
    BatchRow& row = rows_[k];
    row = BatchRow{row.material, row.model};
    try {
      fit_under_claim(in, model, mat, row);
    } catch (const OutputError& e) {
      abort(row, e);
      return;
    } catch (const std::exception& e) {
      row.status = FitStatus::Failed;
      row.reason = e.what();
      row.metrics.clear();
    }
    if (published_) compare(in, mat);
    if (row.status != FitStatus::Elsewhere || last_try) release(mat);
    return_free_memory();  // the fit's grid share and bases: without it a batch's RSS grows with its length
    log_row(row, last_try);
  }

  // An output that cannot be written (full disk, file size limit) fails every later fit too: the
  // batch starts no other fit and run() rethrows the first such error.
  void abort(BatchRow& row, const OutputError& e) {
    row.status = FitStatus::Failed;
    row.reason = e.what();
    std::lock_guard lock(log_mu_);
    if (!output_error_) output_error_ = std::current_exception();
    aborted_ = true;
  }

  void release(Material& mat) {
    std::lock_guard lock(mat.mu);
    if (--mat.remaining > 0) return;
    mat.metrics.clear();
    mat.store.reset();
    mat.data.reset();
    mat.loaded = false;
  }

  void log_row(const BatchRow& row, bool last_try) {
    if (row.status == FitStatus::Elsewhere && !last_try) {
      log(fmt::format("{} {}: claimed by another process; tried again after the others", row.material, row.model));
      return;
    }
    log(batch_progress_line(row, metric_, ++done_, rows_.size()));
  }

  void log_total(const BatchSummary& s) {
    std::string more;
    if (const size_t e = s.count(FitStatus::Elsewhere)) more += fmt::format(", {} running elsewhere", e);
    if (const size_t u = s.count(FitStatus::Unfinished)) more += fmt::format(", {} unfinished", u);
    log(fmt::format("fit-all: {} fits: {} fitted, {} skipped (already saved), {} failed{}{}; {:.1f} s; results in {}",
                    s.rows.size(), s.count(FitStatus::Fitted), s.count(FitStatus::Resumed), s.count(FitStatus::Failed),
                    more, s.interrupted ? " (interrupted)" : "", s.wall_seconds, out_.string()));
  }

  // The data's checksum (for the resume check) without loading the data.
  const std::string& checksum(const BatchInput& in, Material& mat) {
    std::lock_guard lock(mat.mu);
    if (!mat.sha_done) {
      mat.sha_done = true;
      try {
        mat.sha = sha256_file(in.file);
      } catch (const std::exception& e) {
        mat.error = e.what();
      }
    }
    if (!mat.error.empty()) throw InputError("data", mat.error);
    return mat.sha;
  }

  // Loads the data and builds the report metrics once; the caller holds mat.mu.
  void load_locked(const BatchInput& in, Material& mat) {
    if (!mat.error.empty()) throw InputError("data", mat.error);
    if (mat.loaded) return;
    mat.loaded = true;
    try {
      mat.data = load_measured(in.file);
    } catch (const std::exception& e) {
      mat.error = e.what();
      throw;
    }
    mat.store = std::make_unique<MetricStore>(*mat.data);
    for (const std::string& id : report_) {
      try {
        MetricOptions o{opt_.fit.coarsen};
        o.keep = id == metric_;  // the others are evaluated once per fit
        mat.metrics[id] = mat.store->metric(id, o);
      } catch (const InputError& e) {  // MetricUndefined and grids a coarsening cannot make
        mat.undefined[id] = e.what();
      }
    }
  }

  std::vector<MetricReport> report(Material& mat, const Model& model, const ParamValues& values) {
    std::vector<MetricReport> out;
    for (const std::string& id : report_) {
      std::shared_ptr<const Metric> m;
      {
        std::lock_guard lock(mat.mu);
        auto it = mat.metrics.find(id);
        if (it == mat.metrics.end()) {
          out.push_back({id, std::nullopt, mat.undefined[id]});
          continue;
        }
        m = it->second;
      }
      const double v = m->value(model, values);
      if (!std::isfinite(v)) throw FitError(fmt::format("metric {} is not finite at the fitted parameters", id));
      out.push_back({id, v, ""});
    }
    return out;
  }

  fs::path result_file(const BatchRow& row) const { return out_ / row.material / (row.model + ".json"); }

  // The claim protocol of fit_batch.h: claim, clear a killed writer's temporary, keep a matching
  // result or fit and save one.
  void fit_under_claim(const BatchInput& in, const Model& model, Material& mat, BatchRow& row) {
    const std::string sha = checksum(in, mat);
    const FitClaim claim(fit_claim_file(out_, row.material, row.model));
    if (!claim.held()) {
      row.status = FitStatus::Elsewhere;
      return;
    }
    const fs::path json = result_file(row);
    remove_temporaries_of(json);
    if (resume(json, sha, row)) return;
    fit_and_save(in, model, mat, row, sha);
  }

  // True, with the row filled, when `json` holds this fit under these settings.
  bool resume(const fs::path& json, const std::string& sha, BatchRow& row) const {
    const auto saved = read_json(json);
    if (!saved || !fit_job_matches(*saved, row.model, sha, opt_.fit, report_)) return false;
    row.status = FitStatus::Resumed;
    row.reason.clear();
    row.json = json.string();
    row.metrics.clear();
    for (const std::string& id : report_) {
      const auto& v = (*saved)["metrics"][id];
      row.metrics.emplace_back(id, v.is_number() ? std::optional<double>(v.get<double>()) : std::nullopt);
    }
    const auto& f = (*saved)["fit"];
    row.seconds = f.value("seconds", 0.0);
    row.iterations = f.value("iterations", 0);
    row.converged = f.value("converged", false);
    return true;
  }

  void fit_and_save(const BatchInput& in, const Model& model, Material& mat, BatchRow& row, const std::string& sha) {
    MetricStore* store = nullptr;
    {
      std::lock_guard lock(mat.mu);
      load_locked(in, mat);
      store = mat.store.get();
    }
    FitJobResult r = run_fit_job(model, *store, in.file.string(), sha, opt_.fit);
    r.record.metrics = report(mat, model, r.record.values);
    const nlohmann::json doc = fit_job_json(r, opt_.fit, in.material);
    const fs::path json = result_file(row);
    std::error_code ec;
    fs::create_directories(json.parent_path(), ec);
    if (ec) throw OutputError(json.parent_path().string(), "cannot create the folder: " + ec.message());
    write_file_atomically(json, json_text(doc) + "\n");
    row.status = FitStatus::Fitted;
    row.json = json.string();
    for (const MetricReport& m : r.record.metrics) row.metrics.emplace_back(m.id, m.value);
    row.seconds = r.record.seconds;
    row.iterations = r.record.iterations;
    row.converged = r.record.converged;
  }

  // The summary, from the results on disk, written under the summary claim: concurrent batches
  // write it one after the other, and the last one sees every result the others saved.
  BatchSummary summarize() {
    const FitClaim lock(summary_claim_file(out_), /*wait=*/true);
    for (size_t k = 0; k < rows_.size(); ++k) reread(k);
    BatchSummary s;
    s.procedure = opt_.fit.procedure;
    s.fit_metric = metric_;
    for (const auto& in : inputs_) s.materials.push_back(in.material);
    for (const Model* m : models_) s.models.emplace_back(m->name());
    s.rows = rows_;
    if (published_) {
      s.published_file = opt_.compare;
      for (auto& m : materials_) s.published.push_back(m.published);
    }
    s.interrupted = stop_ && stop_->load();
    for (const char* name : {"summary.csv", "table.txt"}) remove_temporaries_of(out_ / name);
    write_file_atomically(out_ / "summary.csv", summary_csv(s));
    write_file_atomically(out_ / "table.txt", summary_table(s));
    return s;
  }

  // A fit this batch did not save: another process may have saved it since, or stopped without.
  void reread(size_t k) {
    BatchRow& row = rows_[k];
    if (row.status != FitStatus::Elsewhere && row.status != FitStatus::Unfinished) return;
    std::error_code ec;
    const fs::path json = result_file(row);
    if (fs::exists(json, ec)) {
      try {
        if (resume(json, checksum(inputs_[k / models_.size()], materials_[k / models_.size()]), row)) return;
      } catch (const std::exception&) {
        // Unreadable data: the row keeps its status; its other fits say why.
      }
    }
    if (row.status == FitStatus::Elsewhere && !claimed_elsewhere(fit_claim_file(out_, row.material, row.model))) {
      row.status = FitStatus::Unfinished;
      row.reason = "another process claimed this fit and saved no result (it failed or was stopped)";
    }
  }

  // The published fit of this material under the fitting metric, once per material.
  void compare(const BatchInput& in, Material& mat) {
    std::lock_guard lock(mat.mu);
    if (mat.published_done) return;
    mat.published_done = true;
    if (!published_names_.count(in.material)) return;
    try {
      load_locked(in, mat);
      const auto it = mat.metrics.find(metric_);
      if (it == mat.metrics.end()) return;
      const Brdf b = published_->brdf(in.material);
      const double v = it->second->value(b.model(), b.values());
      if (std::isfinite(v)) mat.published = v;
    } catch (const std::exception&) {
      // The material's own rows already say why its data cannot be read.
    }
  }

  const std::vector<BatchInput>& inputs_;
  const std::vector<const Model*>& models_;
  const fs::path out_;
  const BatchSettings& opt_;
  const BatchLog& log_;
  const std::atomic<bool>* stop_;
  std::string metric_;
  std::vector<std::string> report_;
  std::vector<Material> materials_;
  std::vector<BatchRow> rows_;
  std::optional<PublishedFits> published_;
  std::set<std::string> published_names_;
  std::mutex log_mu_;
  std::atomic<size_t> done_{0};
  std::atomic<bool> aborted_{false};
  std::exception_ptr output_error_;
};

}  // namespace

void BatchSettings::validate() const {
  fit::validate(fit);
  for (const std::string& id : report) parse_metric_list(id, "report");
  if (jobs < 1 || jobs > kMaxJobs)
    throw SettingError("jobs", fmt::format("must be in [1, {}] (got {})", kMaxJobs, jobs));
}

BatchSummary run_fit_batch(const std::vector<BatchInput>& inputs, const std::vector<const Model*>& models,
                           const fs::path& out_dir, const BatchSettings& settings, const BatchLog& log,
                           const std::atomic<bool>* stop) {
  settings.validate();
  if (models.empty()) throw SettingError("models", "no model to fit");
  check_search_bounds(models, settings.fit.bounds);
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec || !fs::is_directory(out_dir)) throw InputError(out_dir.string(), "cannot create the output folder");
  Batch batch(inputs, models, out_dir, settings, log, stop);
  return batch.run();
}

BatchRow run_batch_fit(const BatchInput& input, const Model& model, const fs::path& out_dir,
                       const BatchSettings& settings) {
  settings.validate();
  BatchSettings one = settings;
  one.compare.clear();  // the published fits are the summary's (summarize_batch)
  const std::vector<BatchInput> inputs{input};
  const std::vector<const Model*> models{&model};
  const BatchLog no_log;
  Batch batch(inputs, models, out_dir, one, no_log, nullptr);
  return batch.run_single(0);
}

BatchSummary summarize_batch(const std::vector<BatchInput>& inputs, const std::vector<const Model*>& models,
                             const fs::path& out_dir, const BatchSettings& settings, std::vector<BatchRow> rows,
                             bool interrupted, double seconds, const BatchLog& log) {
  settings.validate();
  const std::atomic<bool> stop{interrupted};
  Batch batch(inputs, models, out_dir, settings, log, &stop);
  return batch.summarize_rows(std::move(rows), seconds);
}

}  // namespace brdfkit::fit
