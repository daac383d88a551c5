#include "brdfkit/fit/metric/metric_report.h"

#include <sstream>

#include "brdfkit/core/error.h"

namespace brdfkit::fit {

std::vector<MetricReport> report_metrics(const MeasuredBrdf& data, const Model& model, const ParamValues& values,
                                         const std::vector<std::string>& ids, const MetricOptions& opt) {
  std::vector<std::string> all = ids;
  if (all.empty())
    for (auto id : metric_ids()) all.emplace_back(id);
  std::vector<MetricReport> out;
  for (const std::string& id : all) {
    try {
      const Metric metric = make_metric(id, data, opt);
      out.push_back({id, metric.value(model, values), ""});
    } catch (const MetricUndefined& e) {
      out.push_back({id, std::nullopt, e.what()});
    }
  }
  return out;
}

std::vector<std::string> parse_metric_list(const std::string& list) {
  std::vector<std::string> ids;
  std::stringstream ss(list);
  std::string id;
  while (std::getline(ss, id, ',')) {
    if (id.empty()) continue;
    bool known = false;
    for (auto k : metric_ids()) known = known || k == id;
    if (!known) {
      std::string names;
      for (auto k : metric_ids()) names += (names.empty() ? "" : ", ") + std::string(k);
      throw InputError("metric '" + id + "'", "unknown; known metrics: " + names);
    }
    ids.push_back(id);
  }
  return ids;
}

}  // namespace brdfkit::fit
