// The library's errors as Python exceptions, each carrying the library's one-line message:
// bad input (a file, field or parameter) is a ValueError, a bad setting a ValueError naming the
// keyword argument, an output that cannot be written an OSError, a fit that cannot start a
// RuntimeError.
#include <pybind11/pybind11.h>

#include "brdfkit/core/atomic_file.h"
#include "brdfkit/core/error.h"
#include "brdfkit/fit/engine/fit_model.h"
#include "python_api.h"

namespace brdfkit::python {

void bind_errors(py::module_& m) {
  // pybind11 tries the most recently registered translator first: subclasses after their bases.
  const auto input = py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<SettingError>(m, "SettingError", input.ptr());
  py::register_exception<OutputError>(m, "OutputError", PyExc_OSError);
  py::register_exception<fit::FitError>(m, "FitError", PyExc_RuntimeError);
}

py::object to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

}  // namespace brdfkit::python
