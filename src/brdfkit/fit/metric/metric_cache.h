#pragma once
// Sharing of metric domains between the fits and reports of one material. Building a domain on a
// tabulated file means millions of look-ups (RGL: 2.5 M for `ngan` with its albedo norm), and
// `fit` / `fit-all` used to build the same ones for the fit and again for every report. While a
// MetricCache for some data is alive, make_metric on that data builds each (metric, options)
// domain once and hands out copies, and the maximum measured albedo (the norm of ngan and bagher)
// is integrated once per coarsening. A copy is the metric a fresh build gives (the build is
// deterministic), so no value changes. The owner keeps the data alive while the cache lives —
// which is also what makes the data's address a safe key.
#include <memory>
#include <optional>
#include <string_view>

#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/measured/measured_brdf.h"

namespace brdfkit::fit {

class MetricCache {
 public:
  explicit MetricCache(const MeasuredBrdf& data);
  ~MetricCache();
  MetricCache(const MetricCache&) = delete;
  MetricCache& operator=(const MetricCache&) = delete;

 private:
  const MeasuredBrdf* data_;
};

// make_metric as a shared object: the cached one while a MetricCache for `data` lives.
std::shared_ptr<const Metric> shared_metric(std::string_view id, const MeasuredBrdf& data, const MetricOptions& opt);

namespace detail {
// For make_metric and max_measured_albedo: nothing is found or kept for data without a live cache.
std::shared_ptr<const Metric> find_cached_metric(const MeasuredBrdf& data, std::string_view id, const MetricOptions& opt);
void keep_metric(const MeasuredBrdf& data, std::string_view id, const MetricOptions& opt, const Metric& metric);
std::optional<double> find_cached_albedo(const MeasuredBrdf& data, int coarsen);
void keep_albedo(const MeasuredBrdf& data, int coarsen, double albedo);
}  // namespace detail

}  // namespace brdfkit::fit
