// The two steps of a batch spread over processes (fit/batch/fit_batch.h: run_batch_fit per task,
// summarize_batch at the end), for brdfkit/batch.py. A task's row crosses process boundaries as a
// dict of plain values, so any executor can pickle it.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "brdfkit/core/error.h"
#include "brdfkit/fit/batch/fit_batch.h"
#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/fit/metric/metric_report.h"
#include "brdfkit/fit/procedure/procedure.h"
#include "brdfkit/fit/procedure/search_box.h"
#include "brdfkit/models/model_sets.h"
#include "python_api.h"

namespace brdfkit::python {
namespace {

using fit::FitStatus;
constexpr FitStatus kStatuses[] = {FitStatus::Fitted, FitStatus::Resumed, FitStatus::Failed, FitStatus::Elsewhere,
                                   FitStatus::Unfinished};

fit::FitStatus status_from(const std::string& name) {
  for (const fit::FitStatus s : kStatuses)
    if (fit::status_name(s) == name) return s;
  throw InputError("row status", "unknown: " + name);
}

py::dict row_dict(const fit::BatchRow& r) {
  py::dict d;
  d["material"] = r.material;
  d["model"] = r.model;
  d["status"] = std::string(fit::status_name(r.status));
  d["reason"] = r.reason;
  d["json"] = r.json;
  py::list metrics;
  for (const auto& [id, v] : r.metrics) metrics.append(py::make_tuple(id, v ? py::object(py::float_(*v)) : py::none()));
  d["metrics"] = metrics;
  d["seconds"] = r.seconds;
  d["iterations"] = r.iterations;
  d["converged"] = r.converged;
  return d;
}

fit::BatchRow row_from(const py::dict& d) {
  fit::BatchRow r;
  r.material = d["material"].cast<std::string>();
  r.model = d["model"].cast<std::string>();
  r.status = status_from(d["status"].cast<std::string>());
  r.reason = d["reason"].cast<std::string>();
  r.json = d["json"].cast<std::string>();
  for (const auto& m : d["metrics"]) {
    const auto t = m.cast<py::tuple>();
    r.metrics.emplace_back(t[0].cast<std::string>(), t[1].is_none() ? std::nullopt : std::optional(t[1].cast<double>()));
  }
  r.seconds = d["seconds"].cast<double>();
  r.iterations = d["iterations"].cast<int>();
  r.converged = d["converged"].cast<bool>();
  return r;
}

// `report` as `fit-all --report` takes it: "all", or metric ids joined by commas.
fit::BatchSettings batch_settings(const fit::FitSettings& fit, const std::string& report, const std::string& compare) {
  fit::BatchSettings s{.fit = fit,
                       .report = report == "all" ? fit::metric_ids() : fit::parse_metric_list(report),
                       .jobs = 1,
                       .compare = compare};
  s.validate();
  return s;
}

std::vector<const Model*> models_of(const std::vector<std::string>& names) {
  std::vector<const Model*> out;
  for (const std::string& n : names) out.push_back(&model_by_name(n));
  return out;
}

std::vector<fit::BatchInput> inputs_of(const std::vector<std::pair<std::string, std::string>>& pairs) {
  std::vector<fit::BatchInput> out;
  for (const auto& [material, file] : pairs) out.push_back({material, file});
  return out;
}

}  // namespace

void bind_batch(py::module_& m) {
  m.def("_batch_inputs", [](const std::vector<std::string>& args) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const fit::BatchInput& in : fit::list_batch_inputs(args)) out.emplace_back(in.material, in.file.string());
    return out;
  }, py::arg("args"));
  m.def("_batch_models", [](const std::string& list) {
    std::vector<std::string> out;
    for (const Model* model : parse_model_set(list)) out.emplace_back(model->name());
    return out;
  }, py::arg("list"));
  m.def("_batch_check", [](const fit::FitSettings& fit, const std::string& report, const std::string& compare,
                           const std::vector<std::string>& models) {
    fit::check_search_bounds(models_of(models), fit.bounds);
    return fit::fitting_metric(batch_settings(fit, report, compare).fit);
  });
  m.def("_run_batch_fit", [](const std::string& material, const std::string& file, const std::string& model,
                             const std::string& out_dir, const fit::FitSettings& fit,
                             const std::string& report) {
    const fit::BatchSettings s = batch_settings(fit, report, "");
    const Model& mm = model_by_name(model);
    fit::BatchRow row;
    {
      py::gil_scoped_release release;
      row = fit::run_batch_fit({material, file}, mm, out_dir, s);
    }
    return row_dict(row);
  });
  m.def("_summarize_batch", [](const std::vector<std::pair<std::string, std::string>>& inputs,
                               const std::vector<std::string>& models, const std::string& out_dir,
                               const fit::FitSettings& fit, const std::string& report,
                               const std::string& compare, const std::vector<py::dict>& rows, bool interrupted,
                               double seconds, const std::function<void(std::string)>& log) {
    std::vector<fit::BatchRow> r;
    for (const py::dict& d : rows) r.push_back(row_from(d));
    const fit::BatchSettings s = batch_settings(fit, report, compare);
    const fit::BatchLog sink = [&](std::string_view line) {
      if (log) log(std::string(line));
    };
    const fit::BatchSummary summary =
        fit::summarize_batch(inputs_of(inputs), models_of(models), out_dir, s, std::move(r), interrupted, seconds, sink);
    return to_python(fit::summary_json(summary));
  });
  m.def("_progress_line", [](const py::dict& row, const std::string& metric, size_t done, size_t total) {
    return fit::batch_progress_line(row_from(row), metric, done, total);
  });
}

}  // namespace brdfkit::python
