#include "brdfkit/fit/settings/fit_settings.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

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
  for (const auto& [name, box] : bounds)
    if (!std::isfinite(box.first) || !std::isfinite(box.second) || box.first > box.second)
      throw SettingError("bounds",
                         fmt::format("{}: needs finite lower <= upper (got [{}, {}])", name, box.first, box.second));
  if (!(threshold > 0) || !std::isfinite(threshold))
    throw SettingError("threshold", fmt::format("must be a finite number > 0 (got {})", threshold));
}

std::string FitSettings::fitting_metric(const std::string& procedure_metric) const {
  if (!metric.empty()) return metric;
  if (!procedure_metric.empty()) return procedure_metric;
  return "ngan";
}

std::pair<std::string, std::pair<double, double>> parse_search_bound(const std::string& text) {
  const size_t eq = text.find('='), colon = text.find(':', eq == std::string::npos ? 0 : eq);
  const auto number = [&](size_t from, size_t to) {
    const std::string s = text.substr(from, to - from);
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size())
      throw SettingError("bounds", "'" + text + "': '" + s + "' is not a number (NAME=LOWER:UPPER)");
    return v;
  };
  if (eq == 0 || eq == std::string::npos || colon == std::string::npos)
    throw SettingError("bounds", "'" + text + "' is not NAME=LOWER:UPPER (e.g. alpha=0.001:3)");
  return {text.substr(0, eq), {number(eq + 1, colon), number(colon + 1, text.size())}};
}

}  // namespace brdfkit::fit
