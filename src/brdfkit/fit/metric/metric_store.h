#pragma once
// The metric domains of one measured data set, each built once and shared. Building a domain on a
// tabulated file means millions of look-ups (RGL: 2.5 M for `ngan` with its albedo norm), and a
// fit and its reports (or the fits of every model of one material in `fit-all`) need the same
// ones. The store is passed explicitly to whatever builds metrics for the data; a metric it hands
// out is the one make_metric builds (the build is deterministic), so no value depends on sharing.
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <tuple>

#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/measured/measured_brdf.h"

namespace brdfkit::fit {

class MetricStore {
 public:
  // `data` must outlive the store and every metric it hands out.
  explicit MetricStore(const MeasuredBrdf& data) : data_(data) {}
  MetricStore(const MetricStore&) = delete;
  MetricStore& operator=(const MetricStore&) = delete;

  const MeasuredBrdf& data() const { return data_; }
  // Metric `id` with these options, built on first use. Thread-safe: concurrent callers of one
  // key wait for a single build; a build's InputError is rethrown to every caller of that key.
  std::shared_ptr<const Metric> metric(std::string_view id, const MetricOptions& opt = {});
  // Whether metric `id` with these options has been asked of the store (built, or being built).
  bool holds(std::string_view id, const MetricOptions& opt);
  // max_measured_albedo (metric_definition.h) at a coarsening, integrated once.
  double max_albedo(int coarsen);

 private:
  using Key = std::tuple<std::string, int, int, bool>;  // metric id, coarsening, domain choice, keep
  static Key key_of(std::string_view id, const MetricOptions& opt) {
    return {std::string(id), opt.coarsen, int(opt.domain), opt.keep};
  }
  struct Entry {
    std::once_flag built;
    std::shared_ptr<const Metric> metric;
    std::exception_ptr error;
  };
  const MeasuredBrdf& data_;
  std::mutex mu_;
  std::map<Key, std::shared_ptr<Entry>> metrics_;
  std::map<int, std::shared_ptr<std::pair<std::once_flag, double>>> albedo_;
};

}  // namespace brdfkit::fit
