#include "brdfkit/report/report_site.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <mutex>

#include "brdfkit/core/atomic_file.h"
#include "brdfkit/core/json_text.h"
#include "brdfkit/measured/load.h"
#include "brdfkit/render/comparison.h"
#include "brdfkit/render/image_io.h"
#include "brdfkit/report/assets.h"
#include "brdfkit/report/plot_data.h"
#include "brdfkit/report/seed_claims.h"

namespace brdfkit::report {
namespace {

namespace fs = std::filesystem;

std::string html_escape(std::string_view s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// A JSON file and the script that hands the same data to the page (file:// pages cannot fetch).
void write_data(const fs::path& stem, const char* variable, const nlohmann::json& j) {
  const std::string text = json_text(j, -1);
  write_file_atomically(fs::path(stem.string() + ".json"), text + "\n");
  write_file_atomically(fs::path(stem.string() + ".js"), fmt::format("window.{} = {};\n", variable, text));
}

std::string page(const std::string& title, const std::string& root, const std::string& data_script, const std::string& body) {
  return fmt::format(R"(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{0}</title>
<link rel="stylesheet" href="{1}assets/report.css">
<script src="{1}assets/echarts.min.js"></script>
<script src="{2}"></script>
<script src="{1}assets/report.js"></script>
</head><body>
{3}
<p class="note">Made by brdfkit {4}. Charts: Apache ECharts (<a href="{1}assets/ECHARTS-LICENSE.txt">Apache-2.0</a>).</p>
</body></html>
)",
                     html_escape(title), root, data_script, body, BRDFKIT_VERSION);
}

void write_assets(const fs::path& dir) {
  fs::create_directories(dir);
  bool charts = false;
  for (const auto& [name, bytes] : embedded_assets()) {
    write_file_atomically(dir / std::string(name), std::string(bytes));
    charts |= name == "echarts.min.js";
  }
  if (!charts)
    throw std::runtime_error("brdfkit was built without Apache ECharts (node_modules/echarts): run scripts/setup.sh and rebuild");
}

struct MaterialPage {
  nlohmann::json data;
  std::string note;
};

std::vector<NamedBrdf> shown_fits(const MaterialResult& m, int count) {
  std::vector<NamedBrdf> out;
  for (const FitResult& f : m.fits)
    if (int(out.size()) < count) out.push_back({f.model, f.brdf});
  return out;
}

// Renders measured beside the best fits into dir/render*.{png,exr,json}; the measured sphere only
// where the data answer ρ(wi, wo), sampled through the best fit.
nlohmann::json render_material(const MeasuredBrdf* data, const std::vector<NamedBrdf>& fits, const render::Scene& scene,
                               const ReportOptions& opt, const fs::path& dir) {
  std::vector<render::Subject> subjects;
  if (data && answers_eval(*data))
    subjects.push_back({"measured", data->path(), true, render::measured_reflector(*data, fits.front().brdf)});
  for (const NamedBrdf& f : fits) subjects.push_back({f.name, f.name, false, render::model_reflector(f.brdf)});
  render::ComparisonSettings cs;
  cs.render.width = cs.render.height = opt.size;
  cs.render.spp = opt.spp;
  cs.render.seed = opt.seed;
  const render::Comparison c = render::render_comparison(subjects, scene, cs);
  return render::write_comparison(c, dir / "render", true);
}

nlohmann::json fit_entries(const MaterialResult& m, const fs::path& page_dir) {
  nlohmann::json out = nlohmann::json::array();
  for (const FitResult& f : m.fits) {
    nlohmann::json params = nlohmann::json::array();
    for (const auto& p : f.record["params"]) params.push_back({{"name", p["name"]}, {"values", p["values"]}});
    out.push_back({{"model", f.model}, {"json", fs::relative(f.json, page_dir).generic_string()},
                   {"fit_metric", f.record["fit"].value("metric", "")}, {"params", params},
                   {"metrics", f.record["metrics"]}});
  }
  return out;
}

MaterialPage build_material(const MaterialResult& m, const render::Scene& scene, const ReportOptions& opt) {
  const fs::path pages = opt.out_dir / "materials", dir = pages / m.name;
  fs::create_directories(dir);
  MaterialPage p;
  std::unique_ptr<MeasuredBrdf> data;
  if (!m.data_file.empty()) data = load_measured(m.data_file);
  else p.note = "The measured file of this material was not found: fits only.";
  if (data && !answers_eval(*data)) p.note = "These data are scattered samples (" + data->format() + "): no measured sphere can be rendered; plots show the samples.";
  const std::vector<NamedBrdf> fits = shown_fits(m, opt.fits_shown);
  nlohmann::json render = render_material(data.get(), fits, scene, opt, dir);
  nlohmann::json plots;
  if (data) {
    plots["slices"] = incidence_slices(*data, fits);
    plots["maps"] = half_diff_maps(*data, fits.front());
    plots["albedo"] = albedo_curves(*data, fits);
  }
  p.data = {{"name", m.name}, {"data_file", m.data_file.string()}, {"render", render}, {"render_dir", m.name},
            {"fits", fit_entries(m, pages)}, {"plots", plots}, {"note", p.note}};
  return p;
}

std::string material_body(const MaterialResult& m, const MaterialPage& p) {
  std::string imgs;
  const nlohmann::json& r = p.data["render"];
  for (size_t k = 0; k < r["columns"].size(); ++k) {
    const nlohmann::json& col = r["columns"][k];
    const nlohmann::json& f = r["files"]["images"][k];
    std::string cap = html_escape(col["label"].get<std::string>());
    if (col.contains("image_rmse"))
      cap += fmt::format("<br>RMSE {:.4g}, sMAPE {:.3f}, &Delta;E00 {:.2f}", col["image_rmse"].get<double>(),
                         col["mean_smape"].get<double>(), col["mean_delta_e2000"].get<double>());
    imgs += fmt::format("<figure style=\"width: {3}px\"><img src=\"{0}/{1}\" alt=\"{2}\" width=\"{3}\" height=\"{3}\"><figcaption>{4}</figcaption>", m.name,
                        f["render"].get<std::string>(), html_escape(col["label"].get<std::string>()), r["width"].get<int>(), cap);
    for (const char* kind : {"smape", "delta_e"})
      if (f.contains(kind))
        imgs += fmt::format("<img src=\"{0}/{1}\" alt=\"{2} of {3}\" width=\"{4}\" height=\"{4}\">", m.name, f[kind].get<std::string>(),
                            kind, html_escape(col["label"].get<std::string>()), r["width"].get<int>());
    imgs += "</figure>\n";
  }
  const bool plots = !p.data["plots"].is_null();
  return fmt::format(R"(<p><a href="../index.html">&larr; all materials</a></p>
<h1>{0}</h1>
<p class="note">Measured file: <code>{1}</code>. {2} Data behind this page: <a href="{0}.json">{0}.json</a>,
render numbers: <a href="{0}/render.json">render.json</a>, linear renders: <a href="{0}/render.exr">render.exr</a>.</p>
<h2>Renders</h2>
<p class="note">{3}; {4}&times;{4} pixels, {5} samples per pixel, exposure {6:+.2f} EV ({7}). Under each fit: its sMAPE image
(0 to {8}) and its CIEDE2000 &Delta;E image (0 to {9}; Lab white = the reference's 99th-percentile luminance), both in
Green's cube-helix colour map, whose luminance rises from black (0) to white (the top of the range).</p>
<div class="renders">
{10}</div>
{11}
<h2>Parameters and errors</h2>
<div id="params"></div>
)",
                     html_escape(m.name), html_escape(m.data_file.string()), html_escape(p.note), html_escape(r["scene"].get<std::string>()),
                     r["width"].get<int>(), r["spp"].get<int>(), r["exposure_ev"].get<double>(), html_escape(r["tone_map"].get<std::string>()),
                     r["smape_display_max"].get<double>(), r["delta_e_display_max"].get<double>(), imgs,
                     plots ? R"(<h2>Incidence plane: &rho; cos &theta;o (linear and cube root; luminance)</h2>
<div class="grid" id="slices"></div>
<h2>Polar plots of the incidence plane (cube root)</h2>
<div class="grid" id="polar"></div>
<h2>(&theta;h, &theta;d) maps: measured, best fit, ratio</h2>
<div class="grid" id="maps"></div>
<h2>Directional albedo a(&theta;i)</h2>
<div class="chart" id="albedo" data-chart="albedo"></div>)"
                           : "");
}

nlohmann::json index_data(const BatchResults& b) {
  nlohmann::json mats = nlohmann::json::array();
  for (const MaterialResult& m : b.materials) {
    nlohmann::json errors = nlohmann::json::object();
    for (const FitResult& f : m.fits) errors[f.model] = f.record["metrics"];
    mats.push_back({{"name", m.name}, {"page", "materials/" + m.name + ".html"}, {"errors", errors}});
  }
  return {{"models", b.models}, {"metrics", b.metrics}, {"fit_metric", b.fit_metric}, {"materials", mats},
          {"claims", claims_json(measure_seed_claims(b))}, {"results_dir", b.dir.string()}};
}

std::string index_body(const BatchResults& b, const nlohmann::json& idx, const fs::path& out_dir) {
  std::string claims;
  for (const auto& c : idx["claims"])
    claims += fmt::format("<li><b>{}</b> ({}): {} better than {} on {} of {} materials under {}; median error ratio {:.3f}.</li>\n",
                          html_escape(c["claim"].get<std::string>()), html_escape(c["source"].get<std::string>()),
                          c["model_a"].get<std::string>(), c["model_b"].get<std::string>(), c["a_better"].get<int>(),
                          c["materials"].get<int>(), c["metric"].get<std::string>(), c["median_ratio"].get<double>());
  if (claims.empty()) claims = "<li>None of the claims' model pairs were fitted in this batch.</li>";
  return fmt::format(R"(<h1>brdfkit report: {0} materials &times; {1} models</h1>
<p class="note">Fits of <code>{2}</code> (fitting metric {3}). Data behind this page: <a href="data/index.json">index.json</a>,
<a href="{4}">summary.csv</a>.</p>
<h2>Errors</h2>
<p>Metric <select id="metric"></select> &mdash; click a column to sort; the best model of each material is marked.</p>
<table id="error-table"></table>
<h2>Error chart (materials sorted by one model's error, seed 002 Fig. 14)</h2>
<p>Sort by <select id="sort-model"></select></p>
<div class="chart" id="error-chart" data-chart="error-chart"></div>
<h2>Seed claims measured on this batch</h2>
<ul class="claims">{5}</ul>
)",
                     b.materials.size(), b.models.size(), html_escape(b.dir.string()), b.fit_metric,
                     fs::relative(b.dir / "summary.csv", out_dir).generic_string(), claims);
}

}  // namespace

fs::path write_report(const BatchResults& b, const ReportOptions& opt) {
  write_assets(opt.out_dir / "assets");
  fs::create_directories(opt.out_dir / "data");
  render::Scene scene = render::builtin_scene();
  if (opt.env) {
    scene.environment = render::EnvironmentMap(render::read_hdr_image(*opt.env), opt.env_rotation, 1);
    scene.lights.clear();
    scene.description = "environment " + opt.env->filename().string();
  }
  std::mutex log_mutex;
  tbb::parallel_for(size_t(0), b.materials.size(), [&](size_t k) {
    const MaterialResult& m = b.materials[k];
    const MaterialPage p = build_material(m, scene, opt);
    const fs::path stem = opt.out_dir / "materials" / m.name;
    write_data(stem, "BRDFKIT_MATERIAL", p.data);
    write_file_atomically(fs::path(stem.string() + ".html"), page(m.name, "../", m.name + ".js", material_body(m, p)));
    if (opt.log) {
      std::lock_guard lock(log_mutex);
      opt.log(fmt::format("report: {} ({} fits)", m.name, m.fits.size()));
    }
  });
  const nlohmann::json idx = index_data(b);
  write_data(opt.out_dir / "data" / "index", "BRDFKIT_INDEX", idx);
  const fs::path index = opt.out_dir / "index.html";
  write_file_atomically(index, page("brdfkit report", "", "data/index.js", index_body(b, idx, opt.out_dir)));
  return index;
}

}  // namespace brdfkit::report
