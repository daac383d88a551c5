// The catalogue (brdfkit.models(), brdfkit.model(name)) and a model with parameter values
// (brdfkit.Brdf): evaluated, sampled and integrated on arrays, and tabulated as a MERL file.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <vector>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/albedo.h"
#include "brdfkit/models/model.h"
#include "brdfkit/models/model_json.h"
#include "brdfkit/models/tabulate_brdf.h"
#include "direction_arrays.h"
#include "python_api.h"

namespace brdfkit::python {
namespace {

py::object param_table(const Model& model) { return to_python(model_json(model)["params"]); }

// {name: value} for a shared parameter, {name: [r, g, b]} for a per-channel one (and for a shared
// one whose channels differ: a per-channel-shape fit).
py::dict param_dict(const Brdf& b) {
  py::dict out;
  const ParamTable& table = b.model().params();
  const ParamValues& v = b.values();
  for (size_t i = 0; i < table.size(); ++i) {
    const bool same = v.values[0][i] == v.values[1][i] && v.values[1][i] == v.values[2][i];
    if (table[i].scope == Scope::Shared && same) out[py::str(table[i].name)] = v.values[0][i];
    else out[py::str(table[i].name)] = py::make_tuple(v.values[0][i], v.values[1][i], v.values[2][i]);
  }
  return out;
}

// A number sets every channel; a sequence of three sets R, G, B (per-channel parameters only).
void set_param(const ParamTable& table, ParamValues& values, const std::string& name, const py::handle& value) {
  const std::string what = "parameter '" + name + "'";
  try {
    values.set(table, name, value.cast<double>());
    return;
  } catch (const py::cast_error&) {
  }
  std::vector<double> xs;
  try {
    xs = value.cast<std::vector<double>>();
  } catch (const py::cast_error&) {
    throw InputError(what, "expected a number or three numbers (R, G, B)");
  }
  if (xs.size() != 3) throw InputError(what, fmt::format("expected a number or three numbers (R, G, B), got {}", xs.size()));
  for (int c = 0; c < 3; ++c) values.set(table, name, xs[size_t(c)], c);
}

Brdf make_brdf(const Model& model, const py::dict& params) {
  ParamValues values = ParamValues::defaults(model.params());
  for (const auto& [k, v] : params) set_param(model.params(), values, py::str(k), v);
  return Brdf(model, values);
}

// Rows are evaluated in blocks laid out as structure of arrays (Model::eval_batch, one call per
// channel and block: the vectorized loop of DESIGN.md §12).
constexpr std::size_t kBlock = 1024;

void eval_rows(const Brdf& b, const Rows& wi, const Rows& wo, std::size_t n, double* out) {
  std::array<std::vector<double>, 6> soa;
  for (auto& a : soa) a.resize(kBlock);
  std::array<std::vector<double>, 3> rho;
  for (auto& a : rho) a.resize(kBlock);
  const SoaPairs pairs{soa[0].data(), soa[1].data(), soa[2].data(), soa[3].data(), soa[4].data(), soa[5].data()};
  const std::size_t si = wi.n == 1 ? 0 : 3, so = wo.n == 1 ? 0 : 3;  // a single row is broadcast
  for (std::size_t start = 0; start < n; start += kBlock) {
    const std::size_t m = std::min(kBlock, n - start);
    const double* a = wi.data + start * si;
    const double* o = wo.data + start * so;
    for (std::size_t j = 0; j < m; ++j)
      for (std::size_t d = 0; d < 3; ++d) {
        soa[d][j] = a[j * si + d];
        soa[3 + d][j] = o[j * so + d];
      }
    for (int c = 0; c < 3; ++c) b.model().eval_batch(b.values().channel(c), c, m, pairs, rho[size_t(c)].data());
    double* dst = out + 3 * start;
    for (std::size_t j = 0; j < m; ++j)
      for (std::size_t c = 0; c < 3; ++c) dst[3 * j + c] = rho[c][j];
  }
}

DoubleArray eval(const Brdf& b, const DoubleArray& wi_array, const DoubleArray& wo_array) {
  const Rows wi = directions(wi_array, "wi"), wo = directions(wo_array, "wo");
  return pair_results(wi, "wi", wo, "wo", 3, [&](std::size_t n, double* o) { eval_rows(b, wi, wo, n, o); });
}

py::tuple sample(const Brdf& b, const DoubleArray& wo_array, const DoubleArray& u_array) {
  const Rows wo = directions(wo_array, "wo"), u = uniforms(u_array, "u", 3);
  const std::size_t n = paired_count(wo, "wo", u, "u");
  const bool single = wo.single && u.single;
  DoubleArray wi = result_array(n, 3, single);
  py::array_t<bool> valid = single ? py::array_t<bool>(std::vector<py::ssize_t>{}) : py::array_t<bool>(py::ssize_t(n));
  double* w = wi.mutable_data();
  bool* ok = valid.mutable_data();
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < n; ++i) {
      const double* r = u.row(i);
      const auto d = b.sample(vec3(wo.row(i)), Vec2d(r[0], r[1]), r[2]);
      ok[i] = d.has_value();
      for (int k = 0; k < 3; ++k) w[3 * i + size_t(k)] = d ? (*d)[k] : 0.0;
    }
  }
  return py::make_tuple(wi, valid);
}

DoubleArray pdf(const Brdf& b, const DoubleArray& wo_array, const DoubleArray& wi_array) {
  const Rows wo = directions(wo_array, "wo"), wi = directions(wi_array, "wi");
  return pair_results(wo, "wo", wi, "wi", 1, [&](std::size_t n, double* o) {
    for (std::size_t i = 0; i < n; ++i) o[i] = b.pdf(vec3(wo.row(i)), vec3(wi.row(i)));
  });
}

DoubleArray albedo(const Brdf& b, const DoubleArray& theta) {
  const AlbedoIntegrand rho = [&](const Vec3d& wi, const Vec3d& wo) -> std::optional<Rgb> { return b.eval(wi, wo); };
  return albedo_results(theta, [&](double theta_i) { return directional_albedo(rho, theta_i).value; });
}

const char* kBrdfDoc = R"(A model of the catalogue with parameter values.

Brdf(model, params=None, **values): model is a name ('cook-torrance-ggx', sums 'lambert+ward') or
a Model; values by parameter name, a number for every channel or (R, G, B) for a per-channel
parameter; the others keep their defaults. ValueError naming the parameter for an unknown name,
a value outside its formula's domain or three values for a shared parameter.

rho (eval) excludes the cosine: the reflected radiance is integral of L(wi) rho(wi, wo) cos(theta_i) dwi.
Directions are unit vectors in the local frame (z = normal), wi towards the light and wo towards the
viewer, as arrays of shape (n, 3) or (3,).)";

void bind_catalogue(py::module_& m) {
  py::class_<Model, std::unique_ptr<Model, py::nodelete>>(m, "Model", "A model of the catalogue: name, description and parameter table.")
      .def_property_readonly("name", [](const Model& x) { return std::string(x.name()); }, "Its name in the catalogue.")
      .def_property_readonly("description", [](const Model& x) { return std::string(x.description()); },
                             "Its formula, in one line.")
      .def_property_readonly("reciprocal", &Model::reciprocal, "Whether rho(wi, wo) = rho(wo, wi).")
      .def_property_readonly("params", &param_table,
                             "The parameter table: a list of dicts with name, lower, upper, default, scope "
                             "('shared' or 'per-channel'), linear (rho is linear in it) and doc.")
      .def("__repr__", [](const Model& x) { return "<brdfkit.Model " + std::string(x.name()) + ">"; });

  m.def("models", [] { return std::vector<const Model*>(all_models().begin(), all_models().end()); },
        py::return_value_policy::reference, "Every model of the catalogue, in the order `brdfkit models` lists them.");
  m.def("model", [](const std::string& name) { return &model_by_name(name); }, py::arg("name"),
        py::return_value_policy::reference,
        "The model called `name` (a sum 'a+b' of models too); ValueError listing the known names otherwise.");
}

void bind_brdf(py::module_& m) {
  py::class_<Brdf>(m, "Brdf", kBrdfDoc)
      .def(py::init([](const std::string& name, const py::object& params, const py::kwargs& kw) {
             py::dict all = params.is_none() ? py::dict() : py::dict(params);
             for (const auto& [k, v] : kw) all[k] = v;
             return make_brdf(model_by_name(name), all);
           }),
           py::arg("model"), py::arg("params") = py::none())
      .def(py::init([](const Model* model, const py::object& params, const py::kwargs& kw) {
             py::dict all = params.is_none() ? py::dict() : py::dict(params);
             for (const auto& [k, v] : kw) all[k] = v;
             return make_brdf(*model, all);
           }),
           py::arg("model"), py::arg("params") = py::none())
      .def_property_readonly("model", [](const Brdf& b) { return &b.model(); }, py::return_value_policy::reference,
                             "The Model.")
      .def_property_readonly("params", &param_dict,
                             "{name: value} (shared parameters) and {name: (R, G, B)} (per-channel ones).")
      .def("eval", &eval, py::arg("wi"), py::arg("wo"),
           "rho(wi, wo) in 1/sr per channel, cosine excluded: (n, 3) RGB (or (3,)). One core per call; the GIL is "
           "released, so threads evaluate in parallel.")
      .def("sample", &sample, py::arg("wo"), py::arg("u"),
           "Draws wi given wo from the model's importance sampler. u: uniform numbers in [0, 1), shape (n, 3) or "
           "(3,): u[:, 0:2] place the direction, u[:, 2] picks the lobe (and channel). Returns (wi, valid): wi "
           "(n, 3), valid (n,) bool; a draw below the horizon is not valid and its wi is (0, 0, 0) (that mass is "
           "what the pdf integrates short of 1).")
      .def("pdf", &pdf, py::arg("wo"), py::arg("wi"),
           "The density of sample() over wi (solid angle, 1/sr), given wo: shape (n,) (or a number).")
      .def("albedo", &albedo, py::arg("theta_i"),
           "Directional albedo a(theta_i) = integral of rho cos(theta_o) dwo: theta_i in radians in [0, pi/2), a "
           "number or an array; returns (3,) or (n, 3).")
      .def("__repr__", [](const Brdf& b) {
        return fmt::format("<brdfkit.Brdf {} {}>", b.model().name(), py::str(param_dict(b)).cast<std::string>());
      });
}

void bind_tabulate(py::module_& m) {
  py::class_<BrdfTable>(m, "MerlTable", "A BRDF tabulated on the MERL grid (brdfkit.tabulate).")
      .def("save", [](const BrdfTable& t, const std::filesystem::path& path) { merl::write(path, t.table); }, py::arg("path"),
           py::call_guard<py::gil_scoped_release>(), "Writes the MERL .binary file (atomically).")
      .def_property_readonly("cells_written", [](const BrdfTable& t) { return t.table.valid_count(); },
                             "Cells above the horizon, each holding the BRDF at its centre.")
      .def_property_readonly("cells_below_horizon",
                             [](const BrdfTable& t) { return merl::kCellCount - t.table.valid_count(); },
                             "Cells written as not measured (raw -1).")
      .def_property_readonly("cells_clamped", [](const BrdfTable& t) { return t.clamped; },
                             "Cells stored as 0 in place of a negative value (clamp_negative).")
      .def_property_readonly("max_rho", [](const BrdfTable& t) { return py::make_tuple(t.max_rho[0], t.max_rho[1], t.max_rho[2]); },
                             "The largest value per channel (1/sr).");
  m.def("tabulate", &tabulate_brdf, py::arg("brdf"), py::arg("clamp_negative") = false,
        py::call_guard<py::gil_scoped_release>(),
        "The BRDF on the MERL grid (each cell at its centre, cells below the horizon not measured), as "
        "`brdfkit tabulate` writes it. ValueError naming the model when it is NaN, infinite or negative in a cell "
        "(clamp_negative=True stores max(0, rho) instead).");
}

}  // namespace

void bind_models(py::module_& m) {
  bind_catalogue(m);
  bind_brdf(m);
  bind_tabulate(m);
}

}  // namespace brdfkit::python
