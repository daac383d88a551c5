#include "brdfkit/render/comparison.h"

#include <fmt/format.h>

#include "brdfkit/core/atomic_file.h"
#include "brdfkit/core/error.h"
#include "brdfkit/core/json_text.h"
#include "brdfkit/render/image_io.h"
#include "brdfkit/render/tone_map.h"

namespace brdfkit::render {
namespace {

namespace fs = std::filesystem;

// 8-bit tiles of one size side by side in rows (missing tiles: dark grey).
Rgb8Image tile_rgb8(const std::vector<std::vector<const Rgb8Image*>>& rows, int w, int h) {
  size_t cols = 0;
  for (const auto& r : rows) cols = std::max(cols, r.size());
  Rgb8Image out{w * int(cols), h * int(rows.size()), {}};
  out.rgb.assign(size_t(out.width) * size_t(out.height) * 3, 40);
  for (size_t r = 0; r < rows.size(); ++r)
    for (size_t c = 0; c < rows[r].size(); ++c) {
      if (!rows[r][c]) continue;
      for (int y = 0; y < h; ++y)
        std::copy_n(&rows[r][c]->rgb[size_t(y) * size_t(w) * 3], size_t(w) * 3,
                    &out.rgb[(size_t(r) * size_t(h) + size_t(y)) * size_t(out.width) * 3 + c * size_t(w) * 3]);
    }
  return out;
}

std::string describe_tone_map(double ev) {
  return fmt::format("linear radiance x 2^{:.3f}, clamped to [0, 1], sRGB transfer function (IEC 61966-2-1)", ev);
}

}  // namespace

Comparison render_comparison(const std::vector<Subject>& subjects, const Scene& scene, const ComparisonSettings& settings) {
  if (subjects.empty()) throw InputError("render", "nothing to render: give a measured file, a fit or a model");
  Comparison c;
  c.settings = settings;
  c.scene = scene.description;
  for (const Subject& s : subjects) {
    RenderSettings rs = settings.render;
    if (settings.progress) rs.progress = [&](double f) { settings.progress(s.label, f); };
    c.renders.push_back(render_sphere(*s.reflector, scene, rs));
    c.labels.push_back(s.label);
    c.sources.push_back(s.source);
    c.measured.push_back(s.measured);
  }
  const Image& first = c.renders.front().radiance;
  c.has_reference = subjects.front().measured;
  c.exposure = settings.exposure ? *settings.exposure : auto_exposure(first);
  c.white_y = reference_white(first);
  for (size_t k = 0; k < c.renders.size(); ++k) {
    const bool compared = c.has_reference && k > 0;
    const Image& img = c.renders[k].radiance;
    c.errors.push_back(compared ? std::optional<ImageErrors>(compare_images(first, img, c.white_y)) : std::nullopt);
    c.smape.push_back(compared ? smape_image(first, img) : Image());
    c.delta_e.push_back(compared ? delta_e_image(first, img, c.white_y) : Image());
  }
  return c;
}

nlohmann::json comparison_json(const Comparison& c, const nlohmann::json& files) {
  const RenderSettings& r = c.settings.render;
  nlohmann::json cols = nlohmann::json::array();
  for (size_t k = 0; k < c.labels.size(); ++k) {
    nlohmann::json col = {{"label", c.labels[k]}, {"source", c.sources[k]}, {"measured", bool(c.measured[k])},
                          {"dropped_samples", c.renders[k].dropped}};
    if (c.errors[k]) {
      col["image_rmse"] = c.errors[k]->rmse;
      col["mean_smape"] = c.errors[k]->mean_smape;
      col["mean_delta_e2000"] = c.errors[k]->mean_delta_e;
      col["pixels_compared"] = c.errors[k]->pixels;
    }
    cols.push_back(col);
  }
  return {{"format", "brdfkit-render"},
          {"brdfkit_version", BRDFKIT_VERSION},
          {"scene", c.scene},
          {"camera", {{"model", "pinhole on +z looking at a unit sphere at the origin, y up (DESIGN.md 13)"},
                      {"distance", r.camera_distance}}},
          {"width", r.width},
          {"height", r.height},
          {"spp", r.spp},
          {"seed", r.seed},
          {"estimator", "MIS (power heuristic) of the environment's distribution and the BRDF's sampler; point lights exact"},
          {"exposure_ev", c.exposure},
          {"tone_map", describe_tone_map(c.exposure)},
          {"reference", c.has_reference ? nlohmann::json(c.labels.front()) : nlohmann::json()},
          {"delta_e", {{"formula", "CIEDE2000 (Sharma, Wu & Dalal 2005), linear sRGB -> XYZ (D65) -> CIELAB"},
                       {"white_luminance", c.white_y},
                       {"white", "99th-percentile luminance of the reference render"}}},
          {"smape_display_max", c.settings.smape_max},
          {"delta_e_display_max", c.settings.delta_e_max},
          {"columns", cols},
          {"files", files}};
}

nlohmann::json write_comparison(const Comparison& c, const fs::path& stem, bool per_image) {
  const int w = c.settings.render.width, h = c.settings.render.height;
  const std::map<std::string, std::string> text = {{"exposure", fmt::format("{:.3f} EV", c.exposure)},
                                                   {"tone map", describe_tone_map(c.exposure)}};
  std::vector<Rgb8Image> shown, smape, de;
  for (size_t k = 0; k < c.renders.size(); ++k) {
    shown.push_back(tone_map(c.renders[k].radiance, c.exposure));
    smape.push_back(c.errors[k] ? false_color(c.smape[k], c.settings.smape_max) : Rgb8Image{});
    de.push_back(c.errors[k] ? false_color(c.delta_e[k], c.settings.delta_e_max) : Rgb8Image{});
  }
  std::vector<std::vector<const Rgb8Image*>> rows(c.has_reference && c.renders.size() > 1 ? 3 : 1);
  std::vector<const Image*> linear;
  nlohmann::json files = {{"panel", stem.filename().string() + ".png"}, {"exr", stem.filename().string() + ".exr"}};
  for (size_t k = 0; k < c.renders.size(); ++k) {
    rows[0].push_back(&shown[k]);
    for (size_t r = 1; r < rows.size(); ++r) rows[r].push_back(c.errors[k] ? (r == 1 ? &smape[k] : &de[k]) : nullptr);
    linear.push_back(&c.renders[k].radiance);
    if (!per_image) continue;
    const std::string base = fmt::format("{}-{}", stem.filename().string(), k);
    nlohmann::json f = {{"render", base + ".png"}};
    write_png(stem.parent_path() / (base + ".png"), shown[k], text);
    if (c.errors[k]) {
      write_png(stem.parent_path() / (base + "-smape.png"), smape[k], {{"scale", fmt::format("sMAPE 0 to {}", c.settings.smape_max)}});
      write_png(stem.parent_path() / (base + "-de.png"), de[k], {{"scale", fmt::format("Delta E00 0 to {}", c.settings.delta_e_max)}});
      f["smape"] = base + "-smape.png";
      f["delta_e"] = base + "-de.png";
    }
    files["images"].push_back(f);
  }
  write_png(fs::path(stem.string() + ".png"), tile_rgb8(rows, w, h), text);
  write_exr(fs::path(stem.string() + ".exr"), tile_images({linear}));
  const nlohmann::json j = comparison_json(c, files);
  write_file_atomically(fs::path(stem.string() + ".json"), json_text(j) + "\n");
  return j;
}

std::vector<Subject> make_subjects(const std::vector<SubjectInput>& inputs, bool proxy_first_fit) {
  std::optional<Brdf> proxy;
  for (const SubjectInput& in : inputs)
    if (in.fit && !proxy && proxy_first_fit) proxy = in.fit;
  std::vector<Subject> out;
  for (const SubjectInput& in : inputs) {
    if (in.measured) out.push_back({"measured", in.source, true, measured_reflector(*in.measured, proxy)});
    else out.push_back({std::string(in.fit->model().name()), in.source, false, model_reflector(*in.fit)});
  }
  return out;
}

}  // namespace brdfkit::render
