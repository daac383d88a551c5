#pragma once
// Every metric's value for one fitted model (what `fit` prints and `error` recomputes).
#include <string>
#include <vector>

#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/fit/metric/metric_store.h"

namespace brdfkit::fit {

// One metric's value, or why the data cannot answer it.
struct MetricReport {
  std::string id;
  std::optional<double> value;  // nullopt: the metric does not apply to these data (see note)
  std::string note;
};

// Values of `ids` (all metrics when empty) in the order given, on the store's data. A metric the
// data cannot answer (no measured value in its domain, no albedo to normalize by) is reported
// without a value and with the reason, never as NaN; a non-finite model value is an InputError
// (bad parameters). `fitted`, when given, is the metric the fit ran under, whose samples the
// store keeps: every other metric is evaluated this once, so its samples are built chunk by chunk
// and not kept (MetricOptions::keep; a MERL table's cells are 80–160 MB a metric).
std::vector<MetricReport> report_metrics(MetricStore& store, const Model& model, const ParamValues& values,
                                         const std::vector<std::string>& ids, const MetricOptions& opt,
                                         const std::string& fitted = {});

// Splits "a,b,c" and checks each id; SettingError `setting` for an unknown one.
std::vector<std::string> parse_metric_list(const std::string& list, const std::string& setting = "report");

}  // namespace brdfkit::fit
