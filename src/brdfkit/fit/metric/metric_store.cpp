#include "brdfkit/fit/metric/metric_store.h"

#include "brdfkit/fit/metric/metric_definition.h"

namespace brdfkit::fit {

std::shared_ptr<const Metric> MetricStore::metric(std::string_view id, const MetricOptions& opt) {
  std::shared_ptr<Entry> e;
  {
    const std::lock_guard lock(mu_);
    auto& slot = metrics_[key_of(id, opt)];
    if (!slot) slot = std::make_shared<Entry>();
    e = slot;
  }
  std::call_once(e->built, [&] {
    try {
      e->metric = std::make_shared<const Metric>(
          build_metric(id, data_, opt, [this](int coarsen) { return max_albedo(coarsen); }));
    } catch (...) {
      e->error = std::current_exception();
    }
  });
  if (e->error) std::rethrow_exception(e->error);
  return e->metric;
}

bool MetricStore::holds(std::string_view id, const MetricOptions& opt) {
  const std::lock_guard lock(mu_);
  return metrics_.contains(key_of(id, opt));
}

double MetricStore::max_albedo(int coarsen) {
  std::shared_ptr<std::pair<std::once_flag, double>> a;
  {
    const std::lock_guard lock(mu_);
    auto& slot = albedo_[coarsen];
    if (!slot) slot = std::make_shared<std::pair<std::once_flag, double>>();
    a = slot;
  }
  std::call_once(a->first, [&] { a->second = max_measured_albedo(data_, coarsen); });
  return a->second;
}

}  // namespace brdfkit::fit
