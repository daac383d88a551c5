#pragma once
// Every metric's value for one fitted model (what `fit` prints and `error` recomputes).
#include <string>
#include <vector>

#include "brdfkit/fit/fit_record.h"
#include "brdfkit/fit/metric/metric.h"

namespace brdfkit::fit {

// Values of `ids` (all metrics when empty) in the order given. A metric the data cannot answer
// (no measured value in its domain, no albedo to normalize by) is reported without a value and
// with the reason, never as NaN; a non-finite model value is an InputError (bad parameters).
std::vector<MetricReport> report_metrics(const MeasuredBrdf& data, const Model& model, const ParamValues& values,
                                         const std::vector<std::string>& ids, const MetricOptions& opt);

// Splits "a,b,c" and checks each id; InputError for unknown ones.
std::vector<std::string> parse_metric_list(const std::string& list);

}  // namespace brdfkit::fit
