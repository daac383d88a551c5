#pragma once
// Measured beside fitted (seed 002 Fig. 3, seed 004 Figs. 1, 13, 14): every subject rendered with
// the same scene, size, samples and seed; each fit compared with the measurement (the first
// subject, when it is one) by its sMAPE and CIEDE2000 ΔE images and image RMSE, mean sMAPE and
// mean ΔE (seed 004 Eq. 30, Fig. 17b); written as a panel PNG (renders on top, under each fit its
// sMAPE image, then its ΔE image), a linear EXR of the renders side by side, one PNG per image
// for the report, and a JSON of the numbers and of how the images were made.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdfkit/render/image_metrics.h"
#include "brdfkit/render/reflector.h"
#include "brdfkit/render/sphere_renderer.h"

namespace brdfkit::render {

struct Subject {
  std::string label;     // "measured", a model name, …
  std::string source;    // the file it came from (for the JSON)
  bool measured = false;
  std::unique_ptr<Reflector> reflector;
};

struct ComparisonSettings {
  RenderSettings render;
  std::optional<double> exposure;  // EV; auto_exposure() of the first render when absent
  double smape_max = 0.5;          // sMAPE shown black → white over [0, smape_max]
  double delta_e_max = 20;         // ΔE00 shown over [0, delta_e_max]
  std::function<void(const std::string& label, double fraction)> progress;
};

struct Comparison {
  std::vector<std::string> labels, sources;
  std::vector<bool> measured;
  std::vector<RenderResult> renders;
  bool has_reference = false;               // the first subject is a measurement
  std::vector<std::optional<ImageErrors>> errors;  // per subject, against the reference
  std::vector<Image> smape, delta_e;        // per subject (empty images where no reference)
  double exposure = 0, white_y = 1;
  std::string scene;
  ComparisonSettings settings;
};

// What a caller renders: measured data (not owned; it must outlive the subjects) or a fit.
struct SubjectInput {
  std::string source;  // the file it came from
  const MeasuredBrdf* measured = nullptr;
  std::optional<Brdf> fit;  // when not measured
};
// Subjects in the order given, labelled "measured" or by the fit's model. Measured data are drawn
// by the first fit among the inputs mixed with the cosine (proxy_first_fit), or by the cosine
// alone (render/reflector.h).
std::vector<Subject> make_subjects(const std::vector<SubjectInput>& inputs, bool proxy_first_fit);

// InputError when there is no subject.
Comparison render_comparison(const std::vector<Subject>& subjects, const Scene& scene, const ComparisonSettings& settings);

// The numbers and settings as JSON (`files` names the images written next to it).
nlohmann::json comparison_json(const Comparison& c, const nlohmann::json& files);

// Writes <stem>.png (the panel), <stem>.exr (linear renders side by side), <stem>.json and, with
// `per_image`, <stem>-<k>.png, <stem>-<k>-smape.png and <stem>-<k>-de.png for subject k; all
// atomically. Returns the JSON written.
nlohmann::json write_comparison(const Comparison& c, const std::filesystem::path& stem, bool per_image);

}  // namespace brdfkit::render
