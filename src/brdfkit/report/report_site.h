#pragma once
// `brdfkit report`: a static HTML site over a fit-all folder that opens offline (every script and
// style in the folder, report/assets.h): index.html with the error table (sortable, best model per
// material marked, metric switchable), the error chart materials × models (seed 002 Fig. 14) and
// the seed claims measured on the batch; one page per material with its renders (measured beside
// its best fits, with sMAPE and ΔE images, render/comparison.h), plots (report/plot_data.h), and
// each fit's parameters and metrics. Every page links to the JSON behind it.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string_view>

#include "brdfkit/report/batch_results.h"

namespace brdfkit::report {

struct ReportOptions {
  std::filesystem::path out_dir;
  std::optional<std::filesystem::path> env;  // environment map; render/scene.h's built-in lights without
  double env_rotation = 0;
  int size = 192, spp = 64;
  int fits_shown = 3;  // best fits rendered and plotted per material
  std::uint64_t seed = 1;
  std::function<void(std::string_view)> log;
};

// Writes the site and returns the path of its index.html. Files are written atomically; a
// material whose measured file is gone gets a page of its fits alone, saying so.
std::filesystem::path write_report(const BatchResults& results, const ReportOptions& options);

}  // namespace brdfkit::report
