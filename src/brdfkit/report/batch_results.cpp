#include "brdfkit/report/batch_results.h"

#include <algorithm>
#include <fstream>

#include "brdfkit/core/error.h"
#include "brdfkit/fit/param_source.h"

namespace brdfkit::report {
namespace {

namespace fs = std::filesystem;

fs::path find_data_file(const std::string& written, const fs::path& dir) {
  for (const fs::path& p : {fs::path(written), dir / written, dir.parent_path() / written})
    if (!written.empty() && fs::is_regular_file(p)) return p;
  return {};
}

FitResult load_fit(const fs::path& file) {
  std::ifstream in(file);
  nlohmann::json j;
  try {
    in >> j;
  } catch (const std::exception& e) {
    throw InputError(file.string(), std::string("not a fit JSON: ") + e.what());
  }
  fit::LoadedParams p = fit::load_params(file, "");
  return {std::string(p.brdf.model().name()), file, std::move(j), p.brdf};
}

size_t catalogue_position(const std::string& model) {
  const auto all = all_models();
  for (size_t k = 0; k < all.size(); ++k)
    if (all[k]->name() == model) return k;
  return all.size();  // sums of models after the catalogue
}

}  // namespace

std::optional<double> FitResult::metric(const std::string& id) const {
  const auto m = record.find("metrics");
  if (m == record.end() || !m->contains(id) || !(*m)[id].is_number()) return std::nullopt;
  return (*m)[id].get<double>();
}

BatchResults load_batch_results(const fs::path& dir) {
  if (!fs::is_directory(dir)) throw InputError(dir.string(), "not a folder of fit-all results");
  BatchResults b;
  b.dir = dir;
  std::vector<fs::path> folders;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_directory()) folders.push_back(e.path());
  std::sort(folders.begin(), folders.end());
  for (const fs::path& folder : folders) {
    MaterialResult m{folder.filename().string(), {}, {}};
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(folder))
      if (e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) m.fits.push_back(load_fit(f));
    if (m.fits.empty()) continue;
    b.fit_metric = m.fits.front().record["fit"].value("metric", "ngan");
    m.data_file = find_data_file(m.fits.front().record["data"].value("file", ""), dir);
    std::stable_sort(m.fits.begin(), m.fits.end(), [&](const FitResult& x, const FitResult& y) {
      return x.metric(b.fit_metric).value_or(INFINITY) < y.metric(b.fit_metric).value_or(INFINITY);
    });
    for (const FitResult& f : m.fits) {
      if (std::find(b.models.begin(), b.models.end(), f.model) == b.models.end()) b.models.push_back(f.model);
      for (const auto& [id, v] : f.record["metrics"].items())
        if (std::find(b.metrics.begin(), b.metrics.end(), id) == b.metrics.end()) b.metrics.push_back(id);
    }
    b.materials.push_back(std::move(m));
  }
  if (b.materials.empty()) throw InputError(dir.string(), "no fit found (expected <material>/<model>.json from fit-all)");
  std::stable_sort(b.models.begin(), b.models.end(),
                   [](const std::string& x, const std::string& y) { return catalogue_position(x) < catalogue_position(y); });
  const auto it = std::find(b.metrics.begin(), b.metrics.end(), b.fit_metric);
  if (it != b.metrics.end()) std::rotate(b.metrics.begin(), it, it + 1);
  return b;
}

}  // namespace brdfkit::report
