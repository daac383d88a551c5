#pragma once
// Model-to-model fitting for exports: a fit in a model the target cannot write is tabulated into a
// MERL table (measured/merl_tabulate.h, every cell at its centre) and the target's model is fitted
// to that table under the same metric (fit/fit_job.h, the fitting code of `brdfkit fit`). The
// target's error against the tabulated source is the error the export adds; the files and stdout
// state it.
#include <string>

#include "brdfkit/models/model.h"

namespace brdfkit::exporter {

struct RefitResult {
  Brdf brdf;           // the target model with its fitted values
  std::string metric;  // the metric of the refit (the source fit's fitting metric)
  double added_error;  // the target's error against the tabulated source, as `brdfkit fit` reports it
  double seconds;      // tabulation + fit
};

// InputError where the source cannot be tabulated (a non-finite value) or the metric is unknown;
// fit::FitError where no start of the refit is finite.
RefitResult refit(const Brdf& source, const Model& target, const std::string& metric, int starts = 1);

}  // namespace brdfkit::exporter
