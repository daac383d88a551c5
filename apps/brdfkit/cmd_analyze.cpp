// `brdfkit analyze FILE --what backscatter|fresnel|diffraction|albedo|ndf [--model M] [--params fit.json]
// [--json | --csv] [-o FILE]`: observations from measured data (seed 000 §4.1 Eq. 7
// and Eq. 10, seed 004 §4.2) and the tabulated-NDF estimation of seed 002 §5.1. JSON and
// CSV are for plotting; -o writes atomically (JSON, or CSV with --csv).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <fstream>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

#include "brdfkit/analysis/albedo_curve.h"
#include "brdfkit/analysis/backscatter.h"
#include "brdfkit/measured/diffraction_map.h"
#include "brdfkit/analysis/fresnel_extraction.h"
#include "brdfkit/analysis/ndf_estimation.h"
#include "brdfkit/core/atomic_file.h"
#include "brdfkit/core/error.h"
#include "brdfkit/core/file_digest.h"
#include "brdfkit/core/json_text.h"
#include "brdfkit/fit/fit_record.h"
#include "brdfkit/fit/metric/metric_report.h"
#include "brdfkit/fit/engine/fit_model.h"
#include "brdfkit/measured/load.h"
#include "brdfkit/render/hemisphere_plot.h"
#include "command.h"

namespace brdfkit::cli {
namespace {

using nlohmann::json;

struct AnalyzeArgs {
  std::string file, what, model, params, output, space = "linear", families, metric = "ngan", compare, report, plot;
  bool json = false, csv = false;
  int coarsen = 1, iterations = 5, nodes = 0, starts = 1;
  double threshold = 1e-2, max_theta_h = 80;
  std::optional<double> f0;
};

struct Output {
  json doc;
  std::string csv, text;
};

json rgb(const Rgb& v) { return json::array({v[0], v[1], v[2]}); }
template <class A> json arr3(const A& a) { return json::array({a[0], a[1], a[2]}); }
std::string deg(double rad) { return fmt::format("{:.4f}", rad * 180 / kPi); }

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

// A fitted model: from --params (a saved fit), else fitted here to the data under --metric.
std::pair<const Model*, ParamValues> fitted_model(const AnalyzeArgs& a, const MeasuredBrdf& data, std::string& how) {
  if (!a.params.empty()) {
    const fit::FitRecord rec = fit::load_fit_record(a.params);
    const Model& m = model_by_name(rec.model);
    if (!a.model.empty() && a.model != rec.model)
      throw InputError("--model", "'" + a.model + "' differs from the model of " + a.params + " ('" + rec.model + "')");
    how = "parameters from " + a.params;
    return {&m, rec.values};
  }
  const Model& m = model_by_name(a.model.empty() ? "cook-torrance-ggx" : a.model);
  const fit::Metric metric = fit::make_metric(a.metric, data, {a.coarsen});
  const fit::FitResult r = fit::fit_model(m, metric, fit::FitSettings{.starts = a.starts});
  how = fmt::format("fitted here under {} (grid coarsen {}): {} = {:.6g}", a.metric, a.coarsen, a.metric, r.metric_value);
  return {&m, r.values};
}

Output backscatter(const AnalyzeArgs& a, const MeasuredBrdf& data) {
  analysis::BackscatterOptions opt;
  opt.max_theta_h_deg = a.max_theta_h;
  if (a.nodes > 0) opt.nodes = a.nodes;
  if (a.space == "log") opt.space = analysis::SliceFitSpace::Log;
  else if (a.space != "linear") throw InputError("--space", "'" + a.space + "' is not linear or log");
  if (!a.families.empty()) opt.families = split(a.families);
  const analysis::BackscatterAnalysis r = analysis::analyze_backscatter(data, opt);
  Output o;
  json fits = json::array();
  o.text = fmt::format("back-scattering slice wi = wo of {} ({} angles, theta_h <= {} deg), fit space {} (seed 000 Eq. 7, 12)\n",
                       data.path(), r.slice.theta_h.size(), a.max_theta_h, a.space);
  o.text += fmt::format("{:<18} {:>12} {:>12}   {}\n", "family", "err linear", "err log", "parameters (R; G; B)");
  for (const auto& f : r.fits) {
    json ch = json::array();
    std::string params;
    for (int c = 0; c < 3; ++c) {
      json shape = json::object();
      std::string ps = fmt::format("rho_d={:.4g} Fr={:.4g}", f.rho_d[size_t(c)], f.fr[size_t(c)]);
      for (size_t i = 0; i < f.shape_names.size(); ++i) {
        shape[f.shape_names[i]] = f.shape[size_t(c)][i];
        ps += fmt::format(" {}={:.4g}", f.shape_names[i], f.shape[size_t(c)][i]);
      }
      params += (c ? "; " : "") + ps;
      ch.push_back({{"rho_d", f.rho_d[size_t(c)]}, {"Fr", f.fr[size_t(c)]}, {"shape", shape},
                    {"error_linear", f.error_linear[size_t(c)]}, {"error_log", f.error_log[size_t(c)]},
                    {"model", f.model[size_t(c)]}, {"D", f.fitted_d[size_t(c)]}, {"implied_D", f.implied_d[size_t(c)]}});
    }
    fits.push_back({{"family", f.family}, {"mean_error_linear", f.mean_error_linear},
                    {"mean_error_log", f.mean_error_log}, {"channels", ch}});
    o.text += fmt::format("{:<18} {:>12.5f} {:>12.5f}   {}\n", f.family, f.mean_error_linear, f.mean_error_log, params);
  }
  o.text += "err linear: sqrt(sum w (m - rho)^2 / sum w) / max m; err log: sqrt(sum w (ln m - ln rho)^2 / sum w); "
            "w = solid angle of the theta_h band; means over R, G, B\n";
  json slice = json::array();
  o.csv = "theta_h_deg,m_r,m_g,m_b";
  for (const auto& f : r.fits)
    for (const char* c : {"r", "g", "b"}) o.csv += fmt::format(",{0}_model_{1},{0}_D_{1},{0}_implied_D_{1}", f.family, c);
  o.csv += "\n";
  for (size_t k = 0; k < r.slice.theta_h.size(); ++k) {
    slice.push_back({{"theta_h", r.slice.theta_h[k]}, {"m", rgb(r.slice.value[k])}, {"weight", r.slice.weight[k]}});
    o.csv += fmt::format("{},{},{},{}", deg(r.slice.theta_h[k]), r.slice.value[k][0], r.slice.value[k][1], r.slice.value[k][2]);
    for (const auto& f : r.fits)
      for (int c = 0; c < 3; ++c)
        o.csv += fmt::format(",{},{},{}", f.model[size_t(c)][k], f.fitted_d[size_t(c)][k], f.implied_d[size_t(c)][k]);
    o.csv += "\n";
  }
  o.doc = {{"analysis", "backscatter"}, {"fit_space", a.space}, {"max_theta_h_deg", a.max_theta_h},
           {"slice", slice}, {"fits", fits}};
  return o;
}

Output fresnel(const AnalyzeArgs& a, const MeasuredBrdf& data) {
  std::string how;
  const auto [model, values] = fitted_model(a, data, how);
  analysis::FresnelOptions opt;
  if (a.nodes > 0) opt.nodes = a.nodes;
  const analysis::FresnelCurve r = analysis::extract_fresnel(data, *model, values, opt);
  Output o;
  o.text = fmt::format("Fresnel term on the theta_h = 0 slice (seed 000 Eq. 10), model {} ({})\n", model->name(), how);
  o.text += fmt::format("{:>10} {:>30} {:>30}\n", "theta_d", "data F (R G B)", "model F (R G B)");
  o.csv = "theta_d_deg,data_r,data_g,data_b,model_r,model_g,model_b,has_data,reliable\n";
  json rows = json::array();
  for (size_t k = 0; k < r.theta_d.size(); ++k) {
    const Rgb& d = r.data[k];
    const Rgb& m = r.model[k];
    rows.push_back({{"theta_d", r.theta_d[k]}, {"data", r.has_data[k] ? rgb(d) : json(nullptr)}, {"model", rgb(m)},
                    {"reliable", bool(r.reliable[k])}});
    o.csv += fmt::format("{},{},{},{},{},{},{},{},{}\n", deg(r.theta_d[k]), d[0], d[1], d[2], m[0], m[1], m[2],
                         int(r.has_data[k]), int(r.reliable[k]));
    if (k % 5 == 0 || k + 1 == r.theta_d.size())
      o.text += fmt::format("{:>10.2f} {:>30} {:>30}{}\n", r.theta_d[k] * 180 / kPi,
                            r.has_data[k] ? fmt::format("{:.4f} {:.4f} {:.4f}", d[0], d[1], d[2]) : "n/a",
                            fmt::format("{:.4f} {:.4f} {:.4f}", m[0], m[1], m[2]), r.reliable[k] ? "" : "  (theta_d > 70: discarded by seed 000)");
  }
  o.doc = {{"analysis", "fresnel"}, {"model", model->name()}, {"model_source", how}, {"rows", rows}};
  return o;
}

Output diffraction(const AnalyzeArgs& a, const MeasuredBrdf& data) {
  DiffractionOptions opt;
  opt.threshold = a.threshold;
  if (a.nodes > 0) opt.theta_h_cells = opt.theta_d_cells = opt.phi_d_samples = a.nodes;
  const DiffractionMap r = diffraction_map(data, opt);
  Output o;
  o.text = fmt::format("det(grad log rho, grad f) over (theta_h, theta_d), {} x {} cells, rho averaged over {} phi_d "
                       "(seed 004 4.2); diffraction-dominated where |det| < {}\n",
                       r.theta_h_cells, r.theta_d_cells, opt.phi_d_samples, r.threshold);
  const char* names[3] = {"R (0.645 um)", "G (0.526 um)", "B (0.444 um)"};
  json summary = json::array();
  for (int c = 0; c < 3; ++c) {
    o.text += fmt::format("  {}: {} of {} classified cells diffraction-dominated ({:.1f} %)\n", names[c],
                          r.diffraction_cells[size_t(c)], r.classified[size_t(c)], 100 * r.diffraction_fraction[size_t(c)]);
    summary.push_back({{"channel", names[c]}, {"classified", r.classified[size_t(c)]},
                       {"diffraction_cells", r.diffraction_cells[size_t(c)]},
                       {"fraction", r.diffraction_fraction[size_t(c)]}});
  }
  o.csv = "theta_h_deg,theta_d_deg,count,mean_r,mean_g,mean_b,var_r,var_g,var_b,det_r,det_g,det_b,diffraction_r,diffraction_g,diffraction_b\n";
  json cells = json::array();
  for (const auto& c : r.cells) {
    auto det = [&](int ch) { return c.has_det[size_t(ch)] ? json(c.det[size_t(ch)]) : json(nullptr); };
    cells.push_back({{"theta_h", c.theta_h}, {"theta_d", c.theta_d}, {"count", c.count}, {"mean", rgb(c.mean)},
                     {"variance", rgb(c.variance)}, {"det", json::array({det(0), det(1), det(2)})},
                     {"diffraction", arr3(c.diffraction)}});
    auto dstr = [&](int ch) { return c.has_det[size_t(ch)] ? fmt::format("{}", c.det[size_t(ch)]) : std::string(); };
    o.csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", deg(c.theta_h), deg(c.theta_d), c.count,
                         c.mean[0], c.mean[1], c.mean[2], c.variance[0], c.variance[1], c.variance[2], dstr(0), dstr(1),
                         dstr(2), int(c.diffraction[0]), int(c.diffraction[1]), int(c.diffraction[2]));
  }
  o.doc = {{"analysis", "diffraction"}, {"threshold", r.threshold}, {"theta_h_cells", r.theta_h_cells},
           {"theta_d_cells", r.theta_d_cells}, {"phi_d_samples", opt.phi_d_samples}, {"summary", summary},
           {"cells", cells}};
  return o;
}

Output albedo(const AnalyzeArgs& a, const MeasuredBrdf& data) {
  const Model* model = nullptr;
  ParamValues values;
  if (!a.params.empty()) {
    const fit::FitRecord rec = fit::load_fit_record(a.params);
    model = &model_by_name(rec.model);
    values = rec.values;
  } else if (!a.model.empty()) {
    throw InputError("--model", "the albedo of a model needs its parameters: give --params fit.json");
  }
  const analysis::AlbedoCurve r = analysis::albedo_curve(data, model, model ? &values : nullptr);
  Output o;
  o.text = fmt::format("directional albedo of {}{}\n", data.path(), model ? fmt::format(" and of {} ({})", model->name(), a.params) : "");
  o.csv = "theta_i_deg,data_r,data_g,data_b,missing_fraction,model_r,model_g,model_b\n";
  json rows = json::array();
  for (size_t k = 0; k < r.theta_i_deg.size(); ++k) {
    const auto& d = r.data[k];
    const auto& m = r.model[k];
    rows.push_back({{"theta_i_deg", r.theta_i_deg[k]}, {"data", d ? rgb(*d) : json(nullptr)},
                    {"missing_fraction", r.missing_fraction[k]}, {"model", m ? rgb(*m) : json(nullptr)}});
    auto cols = [](const std::optional<Rgb>& v) { return v ? fmt::format("{},{},{}", (*v)[0], (*v)[1], (*v)[2]) : std::string(",,"); };
    o.csv += fmt::format("{},{},{},{}\n", r.theta_i_deg[k], cols(d), r.missing_fraction[k], cols(m));
    if (k % 10 == 0 || k + 1 == r.theta_i_deg.size()) {
      auto txt = [](const std::optional<Rgb>& v) { return v ? fmt::format("{:.4f} {:.4f} {:.4f}", (*v)[0], (*v)[1], (*v)[2]) : std::string("n/a"); };
      o.text += fmt::format("  theta_i {:5.1f}  data {}  (missing {:.3f})  model {}\n", r.theta_i_deg[k], txt(d),
                            r.missing_fraction[k], txt(m));
    }
  }
  o.doc = {{"analysis", "albedo"}, {"model", model ? json(std::string(model->name())) : json(nullptr)}, {"rows", rows}};
  return o;
}

struct NdfModel {
  std::optional<analysis::TabulatedCookTorrance> model;
  ParamValues values;
};

// A table saved by this command: its metrics are recomputed (what `brdfkit error` does for
// catalogue models).
NdfModel saved_ndf(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file, "cannot open");
  json saved;
  try {
    in >> saved;
  } catch (const json::exception& e) {
    throw InputError(file, std::string("not JSON: ") + e.what());
  }
  if (saved.value("model", "") != analysis::TabulatedCookTorrance::kName || !saved.contains("ndf_table"))
    throw InputError(file, "not a tabulated-NDF model saved by `brdfkit analyze --what ndf`");
  NdfModel out;
  out.model.emplace(analysis::TabulatedCookTorrance::from_table_json(saved["ndf_table"], file + ": ndf_table"));
  out.values = ParamValues::defaults(out.model->params());
  const json& params = saved["parameters"];
  for (const auto& p : out.model->params()) {
    if (!params.is_object() || !params.contains(p.name) || !params[p.name].is_array() || params[p.name].size() != 3)
      throw InputError(file, "parameters." + p.name + " must be an array of 3 numbers");
    for (int c = 0; c < 3; ++c) out.values.set(out.model->params(), p.name, params[p.name][size_t(c)].get<double>(), c);
  }
  return out;
}

// seed 002 §5.1's estimate, with what it did in the text and the JSON.
NdfModel estimated_ndf(const AnalyzeArgs& a, const MeasuredBrdf& data, Output& o, json& doc) {
  const fit::Metric metric = fit::make_metric(a.metric, data, {a.coarsen});
  analysis::NdfEstimationOptions opt;
  opt.max_iterations = a.iterations;
  opt.f0 = a.f0;
  if (a.nodes > 0) opt.nodes = a.nodes;
  const analysis::NdfEstimate e = analysis::estimate_tabulated_ndf(metric, opt);
  o.text = fmt::format("tabulated NDF estimated from {} (seed 002 5.1): {} nodes, {} masking iteration(s), F0 {} {:.4f}\n",
                       data.path(), e.theta.size(), e.iterations, a.f0 ? "given" : "fitted", e.f0);
  o.text += fmt::format("  {} during the iterations:", a.metric);
  for (double v : e.residual_history) o.text += fmt::format(" {:.6g}", v);
  o.text += "\n";
  doc["iterations"] = e.iterations;
  doc["residual_history"] = e.residual_history;
  doc["f0_fitted"] = !a.f0.has_value();
  return {e.model(), e.values};
}

// Reference fits of catalogue models (--compare) under the same metric and grid.
void compare_catalogue_fits(const AnalyzeArgs& a, const MeasuredBrdf& data, Output& o, json& doc) {
  json cmp = json::object();
  for (const std::string& name : split(a.compare)) {
    const Model& m = model_by_name(name);
    const fit::Metric metric = fit::make_metric(a.metric, data, {a.coarsen});
    const fit::FitResult r = fit::fit_model(m, metric, fit::FitSettings{.starts = a.starts});
    cmp[name] = r.metric_value;
    o.text += fmt::format("compare    {:<28} {} = {:.6g} (fitted here, {} start(s))\n", name, a.metric, r.metric_value, a.starts);
  }
  if (!cmp.empty()) doc["compare"] = cmp;
}

void write_ndf_plot(const std::string& file, const std::function<double(const Vec3d&)>& d, Output& o) {
  // The distribution over the hemisphere of half vectors, as seed 002 Figs. 11-13 show theirs.
  constexpr double kDecades = 4;
  const render::Image map = render::parabolic_map(d, 512);
  render::write_png(file, render::log_false_color(map, kDecades),
                    {{"plot", "D(h), parabolic map of the hemisphere of half vectors (x right, y up)"},
                     {"scale", fmt::format("log10 D/max over {} decades, cube-helix", kDecades)}});
  o.text += fmt::format("plot       {} (D over the hemisphere, parabolic map, log scale, {} decades)\n", file, kDecades);
}

// Anisotropic data: D over the hemisphere of half vectors (seed 002 5.1 with analysis/
// hemisphere_table.h) from the data's own samples. Its fit is reported as the estimate's own
// residual: no catalogue metric evaluates a 2-D table model.
Output anisotropic_ndf(const AnalyzeArgs& a, const MeasuredBrdf& data) {
  if (!a.params.empty()) throw InputError("--params", "a saved table is isotropic; these data are anisotropic");
  analysis::NdfEstimationOptions opt;
  opt.max_iterations = a.iterations;
  opt.f0 = a.f0;
  if (a.nodes > 0) opt.rings = a.nodes;
  const analysis::AnisotropicNdfEstimate e = analysis::estimate_anisotropic_ndf(data.samples(), opt);
  const analysis::HemisphereTable& t = e.table;
  Output o;
  o.text = fmt::format("tabulated NDF over the hemisphere estimated from {} (seed 002 5.1, anisotropic data): {} rings x {} "
                       "azimuths, {} masking iteration(s), F0 {} {:.4f}\n",
                       data.path(), t.n_theta(), t.n_phi(), e.iterations, a.f0 ? "given" : "fitted", e.f0);
  o.text += "  residual (ngan weighting, own samples) during the iterations:";
  for (double v : e.residual_history) o.text += fmt::format(" {:.6g}", v);
  o.text += "\n";
  json params = json::object();
  const char* names[] = {"kd", "ks", "F0"};  // the order of AnisotropicNdfEstimate::values
  for (size_t i = 0; i < 3; ++i) {
    const Rgb v(e.values.values[0][i], e.values.values[1][i], e.values.values[2][i]);
    params[names[i]] = rgb(v);
    o.text += fmt::format("  {:<8} {:.6g} {:.6g} {:.6g}\n", names[i], v[0], v[1], v[2]);
  }
  json table = {{"theta_deg", json::array()}, {"phi_deg", json::array()}, {"D", e.d}};
  for (int j = 0; j < t.n_theta(); ++j) table["theta_deg"].push_back(t.theta(j) * 180 / kPi);
  for (int k = 0; k < t.n_phi(); ++k) table["phi_deg"].push_back(t.phi(k) * 180 / kPi);
  o.doc = {{"analysis", "ndf"}, {"model", "tabulated-hemisphere"}, {"parameters", params}, {"hemisphere_table", table},
           {"iterations", e.iterations}, {"residual_history", e.residual_history}, {"f0_fitted", !a.f0.has_value()},
           {"data", {{"file", a.file}, {"sha256", sha256_file(a.file)}}}};
  if (!a.plot.empty()) write_ndf_plot(a.plot, [&e](const Vec3d& h) { return e.D(h); }, o);
  o.csv = "theta_deg,phi_deg,D\n";
  for (int j = 0; j < t.n_theta(); ++j)
    for (int k = 0; k < (j == 0 ? 1 : t.n_phi()); ++k)
      o.csv += fmt::format("{},{},{}\n", deg(t.theta(j)), deg(j == 0 ? 0.0 : t.phi(k)), e.d[size_t(t.node(j, k))]);
  return o;
}

Output ndf(const AnalyzeArgs& a, const MeasuredBrdf& data) {
  if (!data.isotropic()) return anisotropic_ndf(a, data);
  const std::vector<std::string> report = a.report.empty() ? std::vector<std::string>{a.metric} : fit::parse_metric_list(a.report);
  Output o;
  json doc = {{"analysis", "ndf"}, {"model", analysis::TabulatedCookTorrance::kName}};
  NdfModel n;
  if (!a.params.empty()) {
    n = saved_ndf(a.params);
    o.text = fmt::format("tabulated-NDF Cook-Torrance model from {}\n", a.params);
  } else {
    n = estimated_ndf(a, data, o, doc);
  }
  const analysis::TabulatedCookTorrance& model = *n.model;
  json params = json::object();
  for (size_t i = 0; i < model.params().size(); ++i)
    params[model.params()[i].name] = json::array({n.values.values[0][i], n.values.values[1][i], n.values.values[2][i]});
  doc["parameters"] = params;
  doc["ndf_table"] = model.table_json();
  doc["data"] = {{"file", a.file}, {"sha256", sha256_file(a.file)}};
  doc["grid_coarsen"] = a.coarsen;
  o.text += fit::format_params(model, n.values);
  fit::MetricStore store(data);
  const auto metrics = fit::report_metrics(store, model, n.values, report, {a.coarsen});
  json mj = json::object();
  for (const auto& m : metrics) mj[m.id] = m.value ? json(*m.value) : json(nullptr);
  doc["metrics"] = mj;
  o.text += "metrics\n" + fit::format_metrics(metrics);
  compare_catalogue_fits(a, data, o, doc);
  if (!a.plot.empty()) write_ndf_plot(a.plot, [&d = model.distribution()](const Vec3d& h) { return d.D(h.z()); }, o);
  o.csv = "theta_deg,D\n";
  for (size_t j = 0; j < model.distribution().theta.size(); ++j)
    o.csv += fmt::format("{},{}\n", deg(model.distribution().theta[j]), model.distribution().value[j]);
  o.doc = doc;
  return o;
}

int run_analyze(const AnalyzeArgs& a) {
  static const std::set<std::string> kinds = {"backscatter", "fresnel", "diffraction", "albedo", "ndf"};
  if (!kinds.count(a.what))
    throw InputError("--what", "'" + a.what + "' is not one of backscatter, fresnel, diffraction, albedo, ndf");
  // The fits and metric grids made here take the fit settings' ranges (fit/settings/fit_settings.h).
  fit::FitSettings{.coarsen = a.coarsen, .starts = a.starts}.validate();
  if (a.nodes < 0) throw InputError("--nodes", "must be >= 0");
  if (!a.plot.empty() && a.what != "ndf") throw InputError("--plot", "draws a distribution: only with --what ndf");
  const auto data = load_measured(a.file);
  Output o;
  if (a.what == "backscatter") o = backscatter(a, *data);
  else if (a.what == "fresnel") o = fresnel(a, *data);
  else if (a.what == "diffraction") o = diffraction(a, *data);
  else if (a.what == "albedo") o = albedo(a, *data);
  else o = ndf(a, *data);
  o.doc["version"] = BRDFKIT_VERSION;
  if (!o.doc.contains("data")) o.doc["data"] = {{"file", a.file}};
  const std::string json_text = brdfkit::json_text(o.doc) + "\n";
  if (!a.output.empty()) write_file_atomically(a.output, a.csv ? o.csv : json_text);
  if (a.json) std::cout << json_text;
  else if (a.csv && a.output.empty()) std::cout << o.csv;
  else {
    std::cout << o.text;
    if (!a.output.empty()) std::cout << fmt::format("saved      {}\n", a.output);
  }
  return 0;
}

const CommandRegistration reg("analyze", [](CLI::App& app) {
  auto* sub = app.add_subcommand("analyze", "Observations from measured data and tabulated-NDF estimation");
  auto a = std::make_shared<AnalyzeArgs>();
  sub->add_option("FILE", a->file, "Measured BRDF (MERL .binary, RGL .bsdf, ALTA slice, ...)")->required();
  sub->add_option("--what", a->what,
                  "backscatter (seed 000 Eq. 7), fresnel (Eq. 10), diffraction (seed 004 4.2), albedo, "
                  "ndf (seed 002 5.1)")
      ->required();
  sub->add_option("--model,-m", a->model, "fresnel: model to fit when no --params (default cook-torrance-ggx)");
  sub->add_option("--params,-p", a->params,
                  "A saved fit (fresnel, albedo) or a table saved by --what ndf (ndf: recompute its metrics)");
  auto* js = sub->add_flag("--json", a->json, "Print JSON");
  auto* cs = sub->add_flag("--csv", a->csv, "Print CSV (or write CSV with -o)");
  js->excludes(cs);
  sub->add_option("-o,--output", a->output, "Write the result (JSON, or CSV with --csv) atomically");
  sub->add_option("--metric", a->metric, "ndf/fresnel: metric to estimate or fit under")->capture_default_str();
  sub->add_option("--report", a->report, "ndf: comma-separated metrics to report (default: --metric)");
  sub->add_option("--compare", a->compare, "ndf: comma-separated catalogue models to fit under the same metric");
  sub->add_option("--starts", a->starts,
                  "fits done here: number of starts (1 to " + std::to_string(fit::FitSettings::kMaxStarts) + ")")
      ->capture_default_str();
  sub->add_option("--coarsen", a->coarsen,
                  "Metric grid coarsening (1 = the papers' grids; 1 to " +
                      std::to_string(fit::FitSettings::kMaxCoarsen) + ")")
      ->capture_default_str();
  sub->add_option("--iterations", a->iterations, "ndf: masking iterations (seed 002: <= 5)")->capture_default_str();
  sub->add_option("--f0", a->f0, "ndf: Schlick F0 given (default: fitted)");
  sub->add_option("--plot", a->plot, "ndf: draw D over the hemisphere of half vectors as a PNG (parabolic map, log scale)");
  sub->add_option("--nodes", a->nodes, "Grid size (backscatter/fresnel angles, ndf table nodes, diffraction cells)");
  sub->add_option("--threshold", a->threshold, "diffraction: |det| threshold (seed 004: 1e-2)")->capture_default_str();
  sub->add_option("--space", a->space, "backscatter: fit space, linear (seed 000 Eq. 12) or log")->capture_default_str();
  sub->add_option("--families", a->families,
                  "backscatter: comma-separated distribution families (default beckmann, ggx, exponential, sgd, "
                  "exponential-power; known: " + fmt::format("{})", fmt::join(analysis::backscatter_families(), ", ")));
  sub->add_option("--max-theta-h", a->max_theta_h, "backscatter: largest theta_h in degrees")->capture_default_str();
  return [a]() { return run_analyze(*a); };
});

}  // namespace
}  // namespace brdfkit::cli
