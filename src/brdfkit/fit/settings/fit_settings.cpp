#include "brdfkit/fit/settings/fit_settings.h"

#include <fmt/format.h>

#include <cmath>

#include "brdfkit/core/error.h"
#include "brdfkit/fit/metric/metric.h"

namespace brdfkit::fit {

namespace {

void check_range(const char* setting, long long value, long long lo, long long hi) {
  if (value < lo || value > hi) throw SettingError(setting, fmt::format("must be in [{}, {}] (got {})", lo, hi, value));
}

}  // namespace

void FitSettings::validate() const {
  if (!metric.empty()) {
    if (metric.find(',') != std::string::npos) throw SettingError("metric", "names one fitting metric (got '" + metric + "')");
    if (!metric_registry().contains(metric)) throw metric_registry().unknown_setting("metric", metric);
  }
  check_range("starts", starts, 1, kMaxStarts);
  check_range("max_iterations", max_iterations, 1, kMaxIterations);
  check_range("coarsen", coarsen, 1, kMaxCoarsen);
  if (!(threshold > 0) || !std::isfinite(threshold))
    throw SettingError("threshold", fmt::format("must be a finite number > 0 (got {})", threshold));
}

std::string FitSettings::fitting_metric(const std::string& procedure_metric) const {
  if (!metric.empty()) return metric;
  if (!procedure_metric.empty()) return procedure_metric;
  return "ngan";
}

}  // namespace brdfkit::fit
