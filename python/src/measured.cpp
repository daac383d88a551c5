// brdfkit.load(path) → Measured: any measured file, evaluated on arrays of directions.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <limits>

#include "brdfkit/core/error.h"
#include "brdfkit/core/file_digest.h"
#include "brdfkit/measured/albedo.h"
#include "brdfkit/measured/load.h"
#include "brdfkit/measured/summary.h"
#include "brdfkit/measured/write_measured.h"
#include "brdfkit/models/model.h"
#include "direction_arrays.h"
#include "python_api.h"

namespace brdfkit::python {

Measured::Measured(const std::string& path) : path_(path), data_(load_measured(path)) {}

const std::string& Measured::sha256() {
  const std::lock_guard guard(mu_);
  if (!sha_) sha_ = sha256_file(path_);
  return *sha_;
}

fit::MetricStore& Measured::store() {
  if (!store_) store_ = std::make_unique<fit::MetricStore>(*data_);
  return *store_;
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

DoubleArray eval(const Measured& self, const DoubleArray& wi_array, const DoubleArray& wo_array) {
  const Rows wi = directions(wi_array, "wi"), wo = directions(wo_array, "wo");
  return pair_results(wi, "wi", wo, "wo", 3, [&](std::size_t n, double* o) {
    for (std::size_t i = 0; i < n; ++i) {
      const auto v = self.data().eval(vec3(wi.row(i)), vec3(wo.row(i)));
      for (int c = 0; c < 3; ++c) o[3 * i + size_t(c)] = v ? (*v)[c] : kNaN;
    }
  });
}

DoubleArray albedo(const Measured& self, const DoubleArray& theta) {
  return albedo_results(theta, [&](double theta_i) {
    const auto a = directional_albedo(self.data(), theta_i);
    if (!a)
      throw InputError(self.path(), "the data answer no direction pair (scattered samples): info()['albedo'] "
                                    "holds the albedo the samples give");
    return a->value;
  });
}

}  // namespace

void bind_measured(py::module_& m) {
  py::class_<Measured>(m, "Measured", R"(A measured BRDF read from a file (brdfkit.load).

MERL .binary, RGL .bsdf (tensor_file), Cornell .brdf and ALTA .alta files, recognized by content.
Its fits and error reports keep the metric domains they build, so a second fit is quicker.)")
      .def(py::init([](const std::filesystem::path& path) { return new Measured(path.string()); }), py::arg("path"),
           py::call_guard<py::gil_scoped_release>(),
           "Reads the file; ValueError naming the file and the problem when it cannot be read.")
      .def_property_readonly("path", &Measured::path, "The file it was read from.")
      .def_property_readonly("format", [](const Measured& d) { return d.data().format(); },
                             "'merl', 'rgl', 'cornell' or 'alta'.")
      .def_property_readonly("dimensions", [](const Measured& d) { return d.data().dimensions(); },
                             "The shape of the data, in words.")
      .def_property_readonly("sha256", &Measured::sha256, py::call_guard<py::gil_scoped_release>(),
                             "The file's SHA-256 (hex), as saved fits record it.")
      .def("eval", &eval, py::arg("wi"), py::arg("wo"), R"(rho(wi, wo) per channel in 1/sr, without the cosine.

wi (towards the light) and wo (towards the viewer): unit vectors in the local frame (z = normal),
arrays of shape (n, 3) or (3,) (one of them may be a single row, used for every row of the other).
Returns (n, 3) RGB (or (3,)). NaN where the data hold no value: a cell that was not measured, or
any pair for scattered samples (Cornell, ALTA), which answer no direction. Non-unit or
non-finite directions raise ValueError naming the row.)")
      .def("albedo", &albedo, py::arg("theta_i"), R"(Directional albedo a(theta_i) = integral of rho cos(theta_o) dw_o.

theta_i in radians in [0, pi/2), a number or an array of n; returns (3,) or (n, 3) RGB. Computed
by quadrature over the half vector (measured/albedo.h); ValueError for scattered samples, whose
albedo info()['albedo'] gives.)")
      .def("info", [](Measured& d) {
        nlohmann::json j;
        {
          py::gil_scoped_release release;
          j = summary_json(summarize(d.data()));
          j["sha256"] = d.sha256();
        }
        return to_python(j);
      }, "What `brdfkit info --json` says of the file: shape, valid share, value ranges, albedo a(theta_i) at 0..80 deg.");
  // brdfkit.convert's two sources; the format comes from the output's extension (write_measured.h).
  // Returns what was written and the warnings, which the Python side raises as warnings.
  using Written = std::pair<std::string, std::vector<std::string>>;
  auto write = [](const RglSource& source, const std::filesystem::path& out, const MeasuredWriteRequest& r) {
    Written w;
    w.first = write_measured(out, source, r, [&w](const std::string& text) { w.second.push_back(text); });
    return w;
  };
  auto request = [](int theta_i, int phi_i, int symmetry, int grid, const std::string& description) {
    return MeasuredWriteRequest{theta_i, phi_i, symmetry, grid, description};
  };
  m.def("_write_measured",
        [=](Measured& d, const std::filesystem::path& out, int theta_i, int phi_i, int symmetry, int grid, const std::string& description) {
          return write([&d](const Vec3d& wi, const Vec3d& wo) { return d.data().eval(wi, wo); }, out,
                       request(theta_i, phi_i, symmetry, grid, description));
        },
        py::call_guard<py::gil_scoped_release>());
  m.def("_write_measured",
        [=](const Brdf& b, const std::filesystem::path& out, int theta_i, int phi_i, int symmetry, int grid, const std::string& description) {
          return write([&b](const Vec3d& wi, const Vec3d& wo) { return std::optional<Rgb>(b.eval(wi, wo)); }, out,
                       request(theta_i, phi_i, symmetry, grid, description));
        },
        py::call_guard<py::gil_scoped_release>());
}

}  // namespace brdfkit::python
