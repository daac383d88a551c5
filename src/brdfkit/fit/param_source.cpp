#include "brdfkit/fit/param_source.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "brdfkit/core/error.h"
#include "brdfkit/core/text.h"
#include "brdfkit/models/published_fits.h"

namespace brdfkit::fit {

namespace {

double parse_number(const std::string& text, const std::string& where) {
  const std::optional<double> v = finite_number(text);
  if (!v) throw InputError(where, "'" + text + "' is not a finite number");
  return *v;
}

// Edit distance, to suggest the material a user probably meant.
size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diag = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string closest_names(const std::vector<std::string>& names, const std::string& wanted, size_t count) {
  std::vector<std::pair<size_t, std::string>> ranked;
  for (const auto& n : names) ranked.emplace_back(edit_distance(n, wanted), n);
  std::stable_sort(ranked.begin(), ranked.end(), [](auto& x, auto& y) { return x.first < y.first; });
  std::string out;
  for (size_t k = 0; k < std::min(count, ranked.size()); ++k) {
    if (k) out += ", ";
    out += ranked[k].second;
  }
  return out;
}

}  // namespace

void apply_param(const ParamTable& table, ParamValues& values, const std::string& arg) {
  const std::string where = "--param '" + arg + "'";
  const size_t eq = arg.find('=');
  if (eq == std::string::npos || eq == 0) throw InputError(where, "expected name=value, name[r|g|b]=value or name=r,g,b");
  std::string name = arg.substr(0, eq);
  const std::string value = arg.substr(eq + 1);
  int channel = -1;
  if (name.back() == ']') {
    const size_t open = name.find('[');
    const std::string ch = open == std::string::npos ? "" : name.substr(open + 1, name.size() - open - 2);
    if (ch == "r" || ch == "0") channel = 0;
    else if (ch == "g" || ch == "1") channel = 1;
    else if (ch == "b" || ch == "2") channel = 2;
    else throw InputError(where, "channel must be one of r, g, b (or 0, 1, 2)");
    name = name.substr(0, open);
  }
  if (value.find(',') != std::string::npos) {
    if (channel >= 0) throw InputError(where, "give one value with a channel index, or three without");
    std::vector<std::string> parts;
    std::stringstream ss(value);
    for (std::string part; std::getline(ss, part, ',');) parts.push_back(part);
    if (parts.size() != 3 || value.back() == ',') throw InputError(where, "expected three comma-separated values r,g,b");
    for (int c = 0; c < 3; ++c) values.set(table, name, parse_number(parts[size_t(c)], where), c);
    return;
  }
  values.set(table, name, parse_number(value, where), channel);
}

ParamValues params_from_args(const ParamTable& table, const std::vector<std::string>& args) {
  ParamValues values = ParamValues::defaults(table);
  for (const auto& a : args) apply_param(table, values, a);
  return values;
}

LoadedParams load_params(const std::filesystem::path& file, const std::string& material) {
  const std::string where = file.string();
  if (std::filesystem::is_directory(file)) throw InputError(where, "is a folder, not a parameter file");
  std::ifstream in(file);
  if (!in) throw InputError(where, "cannot open for reading");
  const bool bbm_text = file.extension() == ".fit";  // published fits in BBM's text form (models/bbm_fit_text.h)
  nlohmann::json doc;
  try {
    if (!bbm_text) doc = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(where, std::string("not valid JSON: ") + e.what());
  }
  if (bbm_text || (doc.is_object() && doc.contains("materials"))) {
    const PublishedFits fits = PublishedFits::read(file);
    const std::vector<std::string> names = fits.materials();
    if (material.empty())
      throw InputError(where, fmt::format("a published-fits file of {} materials: pick one with --material (e.g. {})",
                                          names.size(), fmt::join(names.begin(), names.begin() + std::ptrdiff_t(std::min<size_t>(3, names.size())), ", ")));
    if (!fits.supported()) throw InputError(where, "unsupported: " + fits.unsupported_reason());
    if (!std::binary_search(names.begin(), names.end(), material))
      throw InputError(where, fmt::format("no material '{}' among its {}; closest: {}", material, names.size(),
                                          closest_names(names, material, 5)));
    return {fits.brdf(material), std::nullopt, material};
  }
  if (!material.empty())
    throw InputError(where, "--material '" + material + "' applies to a published-fits file only; this is a fit file");
  FitRecord rec = fit_record_from_json(doc, where);
  const Model& model = model_by_name(rec.model);
  Brdf brdf(model, rec.values);
  return {std::move(brdf), std::move(rec), ""};
}

Brdf load_params_file(const std::filesystem::path& file, const std::string& material) {
  return load_params(file, material).brdf;
}

Brdf brdf_from_arguments(const std::string& model, const std::vector<std::string>& params,
                         const std::filesystem::path& file, const std::string& material) {
  if (model.empty() == file.empty())
    throw InputError("MODEL / --params", "give a model name or a parameter file (--params), not both");
  if (!material.empty() && file.empty()) throw SettingError("material", "needs a published-fits file given with --params");
  if (!model.empty()) {
    const Model& m = model_by_name(model);
    return Brdf(m, params_from_args(m.params(), params));
  }
  const Brdf loaded = load_params_file(file, material);
  ParamValues values = loaded.values();
  for (const auto& a : params) apply_param(loaded.model().params(), values, a);
  return Brdf(loaded.model(), std::move(values));
}

}  // namespace brdfkit::fit
