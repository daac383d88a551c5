// brdfkit.fit(...) → Fit, brdfkit.error(...), saved and published fits: the library calls that
// `brdfkit fit` and `brdfkit error` make, in the same order, so the numbers are the CLI's.
#include <fmt/format.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <fstream>
#include <sstream>

#include "brdfkit/core/atomic_file.h"
#include "brdfkit/core/error.h"
#include "brdfkit/core/json_text.h"
#include "brdfkit/fit/fit_job.h"
#include "brdfkit/fit/metric/metric_report.h"
#include "brdfkit/fit/param_source.h"
#include "brdfkit/fit/procedure/search_box.h"
#include "python_api.h"

namespace brdfkit::python {
namespace {

// A saved fit: the JSON document `brdfkit fit` writes, and what it says.
struct Fit {
  nlohmann::json doc;
  fit::FitRecord record;

  static Fit from_doc(nlohmann::json doc, const std::string& where) {
    fit::FitRecord r = fit::fit_record_from_json(doc, where);
    return Fit{std::move(doc), std::move(r)};
  }
  Brdf brdf() const { return Brdf(model_by_name(record.model), record.values); }
  std::string text() const { return json_text(doc) + "\n"; }
};

Fit parse_fit(const std::string& text, const std::string& where) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(where, std::string("not JSON: ") + e.what());
  }
  return Fit::from_doc(std::move(doc), where);
}

Fit load_fit(const std::filesystem::path& file) {
  const std::string path = file.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  return parse_fit(text.str(), path);
}

fit::Progress progress_callback(const py::object& progress) {
  if (progress.is_none()) return {};
  return [progress](std::string_view line) {
    py::gil_scoped_acquire gil;
    progress(std::string(line));
  };
}

// `brdfkit fit`'s steps (apps/brdfkit/cmd_fit.cpp): validate, fit, report every metric asked, JSON.
Fit run_fit(Measured& data, const Model& model, const fit::FitSettings& settings, const std::string& report,
            const py::object& progress) {
  const std::vector<std::string> ids = fit::parse_metric_list(report);
  fit::validate(settings);
  const Model* const models[] = {&model};
  fit::check_search_bounds(models, settings.bounds);
  const fit::Progress log = progress_callback(progress);
  py::gil_scoped_release release;
  const std::string sha = data.sha256();
  const auto lock = data.lock();
  fit::MetricStore& store = data.store();
  return Fit::from_doc(fit::fit_job_json(fit::fit_and_report(model, store, data.path(), sha, settings, ids, log), settings),
                       "fit");
}

// `brdfkit error`'s numbers: {metric id: value, or None where the data cannot answer it}.
py::dict run_error(Measured& data, const Brdf& brdf, const std::string& metric, int coarsen) {
  const std::vector<std::string> ids = fit::parse_metric_list(metric, "metric");
  if (coarsen < 1 || coarsen > fit::FitSettings::kMaxCoarsen)
    throw SettingError("coarsen", fmt::format("must be in [1, {}]", int(fit::FitSettings::kMaxCoarsen)));
  std::vector<fit::MetricReport> reports;
  {
    py::gil_scoped_release release;
    const auto lock = data.lock();
    reports = fit::report_metrics(data.store(), brdf.model(), brdf.values(), ids, fit::MetricOptions{coarsen});
  }
  py::dict out;
  for (const fit::MetricReport& r : reports) out[py::str(r.id)] = r.value ? py::object(py::float_(*r.value)) : py::none();
  return out;
}

py::dict metric_dict(const Fit& f) {
  py::dict out;
  for (const fit::MetricReport& r : f.record.metrics)
    out[py::str(r.id)] = r.value ? py::object(py::float_(*r.value)) : py::none();
  return out;
}

void bind_settings(py::module_& m) {
  using fit::FitSettings;
  const FitSettings d;
  py::class_<FitSettings>(m, "FitSettings", R"(The settings of a fit: what `brdfkit fit` takes as flags.

procedure: a procedure of DESIGN.md section 8 ('ngan', 'bagher', 'low-e1', 'low-e2', 'hp-2step',
  'hp-1step'), whose metric is the fitting metric; '' or None: a plain fit under `metric`.
metric: the metric of a plain fit ('' = ngan), or an override of the procedure's.
per_channel_shape: one lobe shape per channel.  coarsen: widens every metric grid step.
threshold: hp-2step's diffraction threshold.  starts, seed: random starts and their seed.
max_iterations: per start and level.  coarse_to_fine: solve on sub-samples first.
scan_start: start 0 at the best point of a scan of the shape parameters' box.
bounds: {name: (lower, upper)}, the search box of those parameters instead of the model's
  (inside the formula's domain; lower == upper holds the parameter there).)")
      .def(py::init([](const std::optional<std::string>& procedure, const std::optional<std::string>& metric,
                       bool per_channel_shape, int coarsen, double threshold, int starts, std::uint64_t seed,
                       int max_iterations, bool coarse_to_fine, bool scan_start, const fit::SearchBounds& bounds) {
             FitSettings s{.procedure = procedure.value_or(""),
                           .metric = metric.value_or(""),
                           .per_channel_shape = per_channel_shape,
                           .coarsen = coarsen,
                           .threshold = threshold,
                           .starts = starts,
                           .seed = seed,
                           .max_iterations = max_iterations,
                           .coarse_to_fine = coarse_to_fine,
                           .scan_start = scan_start,
                           .bounds = bounds};
             fit::validate(s);
             return s;
           }),
           py::kw_only(), py::arg("procedure") = py::none(), py::arg("metric") = py::none(),
           py::arg("per_channel_shape") = d.per_channel_shape, py::arg("coarsen") = d.coarsen,
           py::arg("threshold") = d.threshold, py::arg("starts") = d.starts, py::arg("seed") = d.seed,
           py::arg("max_iterations") = d.max_iterations, py::arg("coarse_to_fine") = d.coarse_to_fine,
           py::arg("scan_start") = d.scan_start, py::arg("bounds") = fit::SearchBounds{})
      .def_readonly("procedure", &FitSettings::procedure)
      .def_readonly("metric", &FitSettings::metric)
      .def_readonly("per_channel_shape", &FitSettings::per_channel_shape)
      .def_readonly("coarsen", &FitSettings::coarsen)
      .def_readonly("threshold", &FitSettings::threshold)
      .def_readonly("starts", &FitSettings::starts)
      .def_readonly("seed", &FitSettings::seed)
      .def_readonly("max_iterations", &FitSettings::max_iterations)
      .def_readonly("coarse_to_fine", &FitSettings::coarse_to_fine)
      .def_readonly("scan_start", &FitSettings::scan_start)
      .def_readonly("bounds", &FitSettings::bounds)
      .def_property_readonly("fitting_metric", [](const FitSettings& s) { return fit::fitting_metric(s); },
                             "The metric the fit minimizes.");
}

}  // namespace

void bind_fit(py::module_& m) {
  bind_settings(m);
  py::class_<Fit>(m, "Fit", "A fit as `brdfkit fit` saves it (DESIGN.md section 1): model, parameters, every metric, "
                            "the data's SHA-256 and the settings.")
      .def_property_readonly("model", [](const Fit& f) { return f.record.model; }, "The model fitted.")
      .def_property_readonly("brdf", &Fit::brdf, "The fitted model with its parameter values (a Brdf).")
      .def_property_readonly("metrics", &metric_dict, "{metric id: value, or None where the data cannot answer it}.")
      .def_property_readonly("fit_metric", [](const Fit& f) { return f.record.fit_metric; }, "The metric the fit minimized.")
      .def_property_readonly("iterations", [](const Fit& f) { return f.record.iterations; }, "Solver iterations, all starts and levels.")
      .def_property_readonly("seconds", [](const Fit& f) { return f.record.seconds; }, "Wall time of the fit.")
      .def_property_readonly("converged", [](const Fit& f) { return f.record.converged; }, "Whether the solver converged.")
      .def_property_readonly("message", [](const Fit& f) { return f.record.message; }, "The solver's last message.")
      .def_property_readonly("coarsen", [](const Fit& f) { return f.record.coarsen; }, "Grid coarsening the metrics were computed with (1: the papers' grids).")
      .def_property_readonly("data_file", [](const Fit& f) { return f.record.data_file; }, "The measured file fitted.")
      .def_property_readonly("data_sha256", [](const Fit& f) { return f.record.data_sha256; }, "Its SHA-256.")
      .def_property_readonly("steps", [](const Fit& f) {
        const auto it = f.doc.find("fit");
        return it != f.doc.end() && it->contains("steps") ? to_python((*it)["steps"]) : py::object(py::list());
      }, "What the procedure did, one line per step.")
      .def("to_json", &Fit::text, "The fit JSON, as `brdfkit fit -o` writes it.")
      .def_static("from_json", [](const std::string& text) { return parse_fit(text, "json"); }, py::arg("text"),
                  "A fit from its JSON text; ValueError naming the field when it is not a valid fit.")
      .def("save", [](const Fit& f, const std::filesystem::path& path) { write_file_atomically(path, f.text()); },
           py::arg("path"), "Writes the fit JSON (atomically).")
      .def("__repr__", [](const Fit& f) {
        const auto it = std::find_if(f.record.metrics.begin(), f.record.metrics.end(),
                                     [&](const auto& r) { return r.id == f.record.fit_metric; });
        return fmt::format("<brdfkit.Fit {} {} {}>", f.record.model, f.record.fit_metric,
                           it != f.record.metrics.end() && it->value ? fmt::format("{:.6g}", *it->value) : "n/a");
      });
  m.def("load_fit", &load_fit, py::arg("path"), "A fit saved by `brdfkit fit` or Fit.save.");
  m.def("published", &fit::load_params_file, py::arg("path"), py::arg("material"),
        "A material's published fit (DESIGN.md section 10) as a Brdf; ValueError listing the closest names for an "
        "unknown material.");
  m.def("_fit", &run_fit, py::arg("data"), py::arg("model"), py::arg("settings"), py::arg("report"),
        py::arg("progress"));
  m.def("_error", &run_error, py::arg("data"), py::arg("brdf"), py::arg("metric"), py::arg("coarsen"));
}

}  // namespace brdfkit::python
