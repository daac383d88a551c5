#include "brdfkit/fit/metric/metric_report.h"

#include <sstream>

#include "brdfkit/core/error.h"

namespace brdfkit::fit {

std::vector<MetricReport> report_metrics(MetricStore& store, const Model& model, const ParamValues& values,
                                         const std::vector<std::string>& ids, const MetricOptions& opt,
                                         const std::string& fitted) {
  const std::vector<std::string> all = ids.empty() ? metric_ids() : ids;
  std::vector<MetricReport> out;
  for (const std::string& id : all) {
    MetricOptions o = opt;
    if (!fitted.empty()) o.keep = id == fitted;
    try {
      out.push_back({id, store.metric(id, o)->value(model, values), ""});
    } catch (const MetricUndefined& e) {
      out.push_back({id, std::nullopt, e.what()});
    }
  }
  return out;
}

std::vector<std::string> parse_metric_list(const std::string& list, const std::string& setting) {
  std::vector<std::string> ids;
  std::stringstream ss(list);
  std::string id;
  while (std::getline(ss, id, ',')) {
    if (id.empty()) continue;
    if (!metric_registry().contains(id)) throw metric_registry().unknown_setting(setting, id);
    ids.push_back(id);
  }
  return ids;
}

}  // namespace brdfkit::fit
