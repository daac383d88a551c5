// `brdfkit render [INPUTS…] [--model M --param … | --params FILE [--material NAME]] -o OUT.png`:
// spheres of measured data and of fits side by side (render/comparison.h), lit by an
// equirectangular HDR map (--env), a constant environment (--env-constant) and/or distant point
// lights (--light θ,φ[,I]); with none of them, the built-in light setup (render/scene.h). INPUTS
// are measured files (any format brdfkit reads; the first is the reference of the error images)
// and fit JSONs written by `brdfkit fit`. Writes OUT.png (panel), OUT.exr (linear), OUT.json.
#include <fmt/format.h>
#include <tbb/global_control.h>

#include <iostream>
#include <memory>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/load.h"
#include "brdfkit/render/comparison.h"
#include "brdfkit/render/image_io.h"
#include "brdf_options.h"
#include "command.h"

namespace brdfkit::cli {
namespace {

namespace fs = std::filesystem;

struct RenderArgs {
  std::vector<std::string> inputs, lights;
  BrdfOptions brdf;
  std::string env, output, proxy = "auto";
  std::optional<double> env_constant, exposure;
  double env_rotation = 0, env_intensity = 1;
  int size = 256, spp = 64, threads = 0;
  std::uint64_t seed = 1;
  bool quiet = false;
};

// Subjects in the order given: measured files and fit JSONs from INPUTS, then the model or
// parameter file of the BRDF options. Measured data are sampled through the first fit
// (--proxy auto) or by the cosine (--proxy cosine).
struct Subjects {
  std::vector<std::unique_ptr<MeasuredBrdf>> data;
  std::vector<render::Subject> list;
};
Subjects load_subjects(const RenderArgs& a) {
  if (a.proxy != "auto" && a.proxy != "cosine") throw InputError("--proxy", "expected auto or cosine");
  Subjects s;
  std::vector<render::SubjectInput> inputs;
  for (const std::string& in : a.inputs) {
    if (fs::path(in).extension() == ".json") {
      inputs.push_back({in, nullptr, fit::load_params(in, "").brdf});
    } else {
      s.data.push_back(load_measured(in));
      inputs.push_back({in, s.data.back().get(), std::nullopt});
    }
  }
  if (!a.brdf.model.empty() || !a.brdf.params_file.empty())
    inputs.push_back({a.brdf.params_file.empty() ? a.brdf.model : a.brdf.params_file, nullptr, a.brdf.brdf()});
  s.list = render::make_subjects(inputs, a.proxy == "auto");
  return s;
}

int run_render(const RenderArgs& a) {
  if (a.output.empty()) throw InputError("-o", "an output file is required");
  if (fs::path(a.output).extension() != ".png") throw InputError("-o", "the output must end in .png (OUT.exr and OUT.json are written beside it)");
  if (a.size < 1 || a.size > 8192) throw InputError("--size", "must be between 1 and 8192");
  if (a.spp < 1) throw InputError("--spp", "must be >= 1");
  std::optional<tbb::global_control> limit;
  if (a.threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, size_t(a.threads));
  const render::Scene scene = render::make_scene({a.env, a.env_rotation, a.env_intensity, a.env_constant, a.lights});
  Subjects subjects = load_subjects(a);
  render::ComparisonSettings cs;
  cs.render.width = cs.render.height = a.size;
  cs.render.spp = a.spp;
  cs.render.seed = a.seed;
  cs.exposure = a.exposure;
  if (!a.quiet) cs.progress = [](const std::string& label, double f) { std::cerr << fmt::format("render: {} {:3.0f} %\n", label, 100 * f); };
  const render::Comparison c = render::render_comparison(subjects.list, scene, cs);
  fs::path stem(a.output);
  stem.replace_extension();
  if (stem.has_parent_path()) fs::create_directories(stem.parent_path());
  const nlohmann::json j = render::write_comparison(c, stem, false);
  std::cout << fmt::format("wrote {}.png (panel), {}.exr (linear), {}.json; exposure {:+.2f} EV\n", stem.string(),
                           stem.string(), stem.string(), c.exposure);
  for (size_t k = 0; k < c.labels.size(); ++k)
    if (c.errors[k])
      std::cout << fmt::format("{:<28} image RMSE {:.5g}  mean sMAPE {:.4f}  mean dE00 {:.3f}\n", c.labels[k],
                               c.errors[k]->rmse, c.errors[k]->mean_smape, c.errors[k]->mean_delta_e);
  return 0;
}

const CommandRegistration reg("render", [](CLI::App& app) {
  auto* sub = app.add_subcommand(
      "render", "Render spheres of measured data and fits side by side (env map / point lights), with sMAPE and "
                "CIEDE2000 error images");
  auto a = std::make_shared<RenderArgs>();
  sub->add_option("INPUTS", a->inputs, "Measured files (the first is the reference) and/or fit JSONs, in panel order");
  // The BRDF options of eval/tabulate, with the model as an option: INPUTS takes the positionals.
  sub->add_option("--model", a->brdf.model, "A model name (see `brdfkit models`) rendered with its --param values");
  sub->add_option("--param", a->brdf.params, "name=value, name[r|g|b]=value or name=r,g,b for --model or --params; repeatable");
  sub->add_option("--params,-p", a->brdf.params_file, "A fit saved by `brdfkit fit`, or a published-fits file (with --material)");
  sub->add_option("--material", a->brdf.material, "The material of a published-fits file");
  sub->add_option("--env", a->env, "Equirectangular HDR environment map (.exr or .hdr), linear radiance");
  sub->add_option("--env-constant", a->env_constant, "A constant environment of this radiance instead of a map");
  sub->add_option("--env-rotation", a->env_rotation, "Turn the map about the vertical axis (degrees)")->capture_default_str();
  sub->add_option("--env-intensity", a->env_intensity, "Multiply the map's radiance")->capture_default_str();
  sub->add_option("--light", a->lights,
                  "A distant light theta,phi[,I] or theta,phi,R,G,B: theta from the camera axis, phi counter-clockwise "
                  "from the image's right (degrees); repeatable");
  sub->add_option("--size", a->size, "Image width and height of each sphere (pixels)")->capture_default_str();
  sub->add_option("--spp", a->spp, "Samples per pixel")->capture_default_str();
  sub->add_option("--seed", a->seed, "Seed of the per-pixel random streams")->capture_default_str();
  sub->add_option("--threads", a->threads, "Threads (0: all cores); the image does not depend on it");
  sub->add_option("--exposure", a->exposure, "PNG exposure in EV (default: the reference's 99th percentile at 0.9)");
  sub->add_option("--proxy", a->proxy, "Sampler for measured data: auto (the first fit given, else cosine) or cosine")
      ->capture_default_str();
  sub->add_option("-o,--output", a->output, "Output panel OUT.png (OUT.exr and OUT.json beside it)")->required();
  sub->add_flag("--quiet,-q", a->quiet, "No progress on stderr");
  return [a]() { return run_render(*a); };
});

}  // namespace
}  // namespace brdfkit::cli
