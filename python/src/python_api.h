#pragma once
// The pieces of the extension module `_brdfkit`, one file per part of the library it exposes;
// python/brdfkit/__init__.py is the public face (docstrings of the functions it defines there).
// Every long call releases the GIL; library errors become the Python exceptions of module.cpp.
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "brdfkit/fit/metric/metric_store.h"
#include "brdfkit/measured/measured_brdf.h"

namespace brdfkit::python {

namespace py = pybind11;

// A measured file as Python holds it: the data, its SHA-256 (computed when first asked) and the
// metric domains of its fits and error reports (kept between calls, as one CLI command keeps them).
class Measured {
 public:
  explicit Measured(const std::string& path);
  const MeasuredBrdf& data() const { return *data_; }
  const std::string& path() const { return path_; }
  const std::string& sha256();
  // The store, locked for the caller's use: one fit or report at a time per file.
  std::unique_lock<std::mutex> lock() { return std::unique_lock(mu_); }
  fit::MetricStore& store();  // the caller holds lock()

 private:
  std::string path_;
  std::unique_ptr<MeasuredBrdf> data_;
  std::optional<std::string> sha_;
  std::unique_ptr<fit::MetricStore> store_;
  std::mutex mu_;
};

// A JSON document as Python objects (dict, list, float, str, None).
py::object to_python(const nlohmann::json& j);

void bind_errors(py::module_& m);
void bind_measured(py::module_& m);
void bind_models(py::module_& m);
void bind_fit(py::module_& m);
void bind_batch(py::module_& m);
void bind_render(py::module_& m);
void bind_export(py::module_& m);

}  // namespace brdfkit::python
