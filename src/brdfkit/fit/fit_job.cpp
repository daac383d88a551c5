#include "brdfkit/fit/fit_job.h"

#include <cmath>

#include "brdfkit/core/error.h"
#include "brdfkit/core/json_text.h"
#include "brdfkit/fit/metric/metric_report.h"

namespace brdfkit::fit {

FitJobResult run_fit_job(const Model& model, MetricStore& store, const std::string& file, const std::string& sha256,
                         const FitSettings& settings, const Progress& progress) {
  require_json_text(file);  // the saved fit names its data file: refuse a name JSON cannot hold before fitting
  ProcedureResult pr = run_procedure(model, store, settings, progress);
  FitJobResult r;
  r.fit = pr.fit;
  r.steps = std::move(pr.steps);
  if (pr.fit.scan_points > 0)  // FitSettings::scan_start
    r.steps.push_back("start 0 = best of " + std::to_string(pr.fit.scan_points) + " scan points (fit/engine/start_scan.h)");
  FitRecord& rec = r.record;
  rec.model = std::string(model.name());
  rec.values = pr.fit.values;
  rec.data_file = file;
  rec.data_sha256 = sha256;
  rec.fit_metric = pr.metric;
  rec.starts = settings.starts;
  rec.seed = settings.seed;
  rec.iterations = pr.fit.iterations;
  rec.seconds = pr.fit.seconds;
  rec.converged = pr.fit.converged;
  rec.message = pr.fit.message;
  rec.coarsen = settings.coarsen;
  rec.per_channel_shape = settings.per_channel_shape;  // also when the channels' shapes happen to coincide
  for (const auto& channel : rec.values.values)
    for (double x : channel)
      if (!std::isfinite(x)) throw FitError("the fit produced a non-finite parameter value");
  return r;
}

FitJobResult fit_and_report(const Model& model, MetricStore& store, const std::string& file, const std::string& sha256,
                            const FitSettings& settings, const std::vector<std::string>& report,
                            const Progress& progress) {
  FitJobResult r = run_fit_job(model, store, file, sha256, settings, progress);
  r.record.metrics =
      report_metrics(store, model, r.record.values, report, MetricOptions{settings.coarsen}, r.record.fit_metric);
  return r;
}

nlohmann::json fit_job_json(const FitJobResult& r, const FitSettings& settings, const std::string& material) {
  nlohmann::json j = to_json(r.record);
  j["fit"]["procedure"] = settings.procedure.empty() ? nlohmann::json(nullptr) : nlohmann::json(settings.procedure);
  j["fit"]["per_channel_shape"] = settings.per_channel_shape;
  j["fit"]["max_iterations"] = settings.max_iterations;
  j["fit"]["best_start"] = r.fit.best_start;
  j["fit"]["start_scan_points"] = r.fit.scan_points;  // start 0 = best of this many scan points; 0: the defaults
  j["fit"]["steps"] = r.steps;
  if (!settings.bounds.empty()) j["fit"]["bounds"] = settings.bounds;  // {"alpha": [lower, upper]}
  if (!material.empty()) j["data"]["material"] = material;
  return j;
}

namespace {

template <class T> bool field_is(const nlohmann::json& obj, const char* key, const T& want) {
  if (!obj.is_object() || !obj.contains(key)) return false;
  try {
    return obj.at(key).get<T>() == want;
  } catch (const nlohmann::json::exception&) {
    return false;
  }
}

}  // namespace

bool fit_job_matches(const nlohmann::json& saved, const std::string& model, const std::string& sha256,
                     const FitSettings& opt, const std::vector<std::string>& report) {
  if (!saved.is_object() || !field_is<std::string>(saved, "format", "brdfkit-fit")) return false;
  if (!field_is<std::string>(saved, "brdfkit_version", BRDFKIT_VERSION)) return false;
  if (!field_is<std::string>(saved, "model", model)) return false;
  if (!saved.contains("data") || !field_is<std::string>(saved["data"], "sha256", sha256)) return false;
  if (!field_is<int>(saved, "grid_coarsen", opt.coarsen)) return false;
  if (!saved.contains("fit")) return false;
  const auto& f = saved["fit"];
  if (!f.is_object() || !f.contains("procedure")) return false;
  if (opt.procedure.empty() ? !f["procedure"].is_null() : !field_is<std::string>(f, "procedure", opt.procedure))
    return false;
  if (!field_is<std::string>(f, "metric", fitting_metric(opt)) || !field_is<int>(f, "starts", opt.starts) ||
      !field_is<std::uint64_t>(f, "seed", opt.seed) || !field_is<int>(f, "max_iterations", opt.max_iterations) ||
      !field_is<bool>(f, "per_channel_shape", opt.per_channel_shape))
    return false;
  if (opt.bounds.empty() ? f.contains("bounds") : !field_is<SearchBounds>(f, "bounds", opt.bounds)) return false;
  // Values: the model's parameters, each three finite numbers (a truncated or edited file is refitted).
  const Model* m = nullptr;
  try {
    m = &model_by_name(model);
  } catch (const InputError&) {
    return false;
  }
  const auto& params = saved.contains("params") ? saved["params"] : nlohmann::json();
  if (!params.is_array() || params.size() != m->params().size()) return false;
  for (size_t i = 0; i < params.size(); ++i) {
    if (!field_is<std::string>(params[i], "name", m->params()[i].name)) return false;
    const auto& v = params[i].contains("values") ? params[i]["values"] : nlohmann::json();
    if (!v.is_array() || v.size() != 3) return false;
    for (const auto& x : v)
      if (!x.is_number() || !std::isfinite(x.get<double>())) return false;
  }
  const auto& metrics = saved.contains("metrics") ? saved["metrics"] : nlohmann::json();
  if (!metrics.is_object()) return false;
  for (const std::string& id : report)
    if (!metrics.contains(id) || !(metrics[id].is_number() || metrics[id].is_null())) return false;
  return true;
}

}  // namespace brdfkit::fit
