// brdfkit.render(...): measured data and fits rendered side by side, with the error images
// (render/comparison.h), returned as arrays and optionally written as `brdfkit render` writes them.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <filesystem>

#include "brdfkit/core/error.h"
#include "brdfkit/render/comparison.h"
#include "brdfkit/render/scene.h"
#include "python_api.h"

namespace brdfkit::python {
namespace {

// (H, W, 3) linear RGB, or (H, W) of the first channel (ΔE images hold one value per pixel).
py::array_t<double> image_array(const render::Image& im, bool one_channel) {
  const size_t channels = one_channel ? 1 : 3;
  std::vector<py::ssize_t> shape{im.height, im.width};
  if (!one_channel) shape.push_back(3);
  py::array_t<double> out(shape);
  double* o = out.mutable_data();
  for (size_t k = 0; k < im.size(); ++k)
    for (size_t c = 0; c < channels; ++c) o[k * channels + c] = im.pixels[k][int(c)];
  return out;
}

py::dict comparison_dict(const render::Comparison& c, const nlohmann::json& summary) {
  py::list images, smape, delta_e, errors, coverage;
  for (size_t k = 0; k < c.labels.size(); ++k) {
    images.append(image_array(c.renders[k].radiance, false));
    const render::Image& cov = c.renders[k].radiance;
    py::array_t<bool> mask({py::ssize_t(cov.height), py::ssize_t(cov.width)});
    for (size_t i = 0; i < cov.size(); ++i) mask.mutable_data()[i] = cov.covered[i] != 0;
    coverage.append(mask);
    const bool compared = c.errors[k].has_value();
    smape.append(compared ? py::object(image_array(c.smape[k], false)) : py::none());
    delta_e.append(compared ? py::object(image_array(c.delta_e[k], true)) : py::none());
    if (compared) {
      py::dict e;
      e["rmse"] = c.errors[k]->rmse;
      e["mean_smape"] = c.errors[k]->mean_smape;
      e["mean_delta_e"] = c.errors[k]->mean_delta_e;
      errors.append(e);
    } else {
      errors.append(py::none());
    }
  }
  py::dict out;
  out["labels"] = c.labels;
  out["sources"] = c.sources;
  out["images"] = images;
  out["covered"] = coverage;
  out["smape"] = smape;
  out["delta_e"] = delta_e;
  out["errors"] = errors;
  out["exposure"] = c.exposure;
  out["summary"] = to_python(summary);
  return out;
}

py::dict run_render(const py::list& subjects, const std::string& output, const render::SceneSettings& scene_settings,
                    int size, int spp, std::uint64_t seed, std::optional<double> exposure, const std::string& proxy,
                    const py::object& progress) {
  if (proxy != "auto" && proxy != "cosine") throw SettingError("proxy", "expected 'auto' or 'cosine'");
  if (size < 1 || size > 8192) throw SettingError("size", "must be between 1 and 8192");
  if (spp < 1) throw SettingError("spp", "must be >= 1");
  if (!output.empty() && std::filesystem::path(output).extension() != ".png")
    throw SettingError("output", "must end in .png (OUT.exr and OUT.json are written beside it)");
  std::vector<render::SubjectInput> inputs;
  for (const py::handle& s : subjects) {
    const auto t = s.cast<py::tuple>();
    const std::string source = t[0].cast<std::string>();
    if (py::isinstance<Measured>(t[1])) inputs.push_back({source, &t[1].cast<const Measured&>().data(), std::nullopt});
    else inputs.push_back({source, nullptr, t[1].cast<Brdf>()});
  }
  render::ComparisonSettings cs;
  cs.render.width = cs.render.height = size;
  cs.render.spp = spp;
  cs.render.seed = seed;
  cs.exposure = exposure;
  if (!progress.is_none())
    cs.progress = [progress](const std::string& label, double f) {
      py::gil_scoped_acquire gil;
      progress(label, f);
    };
  std::optional<render::Comparison> c;
  nlohmann::json summary;
  {
    py::gil_scoped_release release;
    const render::Scene scene = render::make_scene(scene_settings);
    c.emplace(render::render_comparison(render::make_subjects(inputs, proxy == "auto"), scene, cs));
    if (output.empty()) {
      summary = render::comparison_json(*c, nlohmann::json::object());
    } else {
      std::filesystem::path stem(output);
      stem.replace_extension();
      if (stem.has_parent_path()) std::filesystem::create_directories(stem.parent_path());
      summary = render::write_comparison(*c, stem, false);
    }
  }
  return comparison_dict(*c, summary);
}

}  // namespace

void bind_render(py::module_& m) {
  py::class_<render::SceneSettings>(m, "_SceneSettings")
      .def(py::init([](const std::string& env, double rotation, double intensity, std::optional<double> constant,
                       const std::vector<std::string>& lights) {
        return render::SceneSettings{env, rotation, intensity, constant, lights};
      }));
  m.def("_render", &run_render);
}

}  // namespace brdfkit::python
