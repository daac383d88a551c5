#include "brdfkit/fit/metric/metric_cache.h"

#include <map>
#include <mutex>
#include <string>
#include <tuple>

namespace brdfkit::fit {

namespace {

using Key = std::tuple<std::string, int, int>;  // metric id, coarsening, domain choice

struct Entry {
  int owners = 0;  // live MetricCache objects for this data (nested scopes share one entry)
  std::map<Key, std::shared_ptr<const Metric>> metrics;
  std::map<int, double> albedo;  // by coarsening
};

// One registry for the process: fit-all's threads fit different materials (and models of one
// material) at once.
std::mutex registry_mu;
std::map<const MeasuredBrdf*, Entry> registry;

Key key(std::string_view id, const MetricOptions& opt) { return {std::string(id), opt.coarsen, int(opt.domain)}; }

}  // namespace

MetricCache::MetricCache(const MeasuredBrdf& data) : data_(&data) {
  std::lock_guard lock(registry_mu);
  ++registry[data_].owners;
}

MetricCache::~MetricCache() {
  std::lock_guard lock(registry_mu);
  auto it = registry.find(data_);
  if (it != registry.end() && --it->second.owners == 0) registry.erase(it);
}

namespace detail {

std::shared_ptr<const Metric> find_cached_metric(const MeasuredBrdf& data, std::string_view id, const MetricOptions& opt) {
  std::lock_guard lock(registry_mu);
  auto it = registry.find(&data);
  if (it == registry.end()) return nullptr;
  auto m = it->second.metrics.find(key(id, opt));
  return m == it->second.metrics.end() ? nullptr : m->second;
}

void keep_metric(const MeasuredBrdf& data, std::string_view id, const MetricOptions& opt, const Metric& metric) {
  {
    std::lock_guard lock(registry_mu);
    auto it = registry.find(&data);
    if (it == registry.end() || it->second.metrics.count(key(id, opt))) return;
  }
  auto copy = std::make_shared<const Metric>(metric);  // copied outside the lock
  std::lock_guard lock(registry_mu);
  auto it = registry.find(&data);
  if (it != registry.end()) it->second.metrics.emplace(key(id, opt), std::move(copy));
}

std::optional<double> find_cached_albedo(const MeasuredBrdf& data, int coarsen) {
  std::lock_guard lock(registry_mu);
  auto it = registry.find(&data);
  if (it == registry.end()) return std::nullopt;
  auto a = it->second.albedo.find(coarsen);
  return a == it->second.albedo.end() ? std::nullopt : std::optional<double>(a->second);
}

void keep_albedo(const MeasuredBrdf& data, int coarsen, double albedo) {
  std::lock_guard lock(registry_mu);
  auto it = registry.find(&data);
  if (it != registry.end()) it->second.albedo.emplace(coarsen, albedo);
}

}  // namespace detail

}  // namespace brdfkit::fit
