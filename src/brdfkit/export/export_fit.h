#pragma once
// `brdfkit export`'s work: a fit (model + values, and its saved record when there is one) written
// to a target format. A fit in one of the target's own models is written exactly; any other is
// refitted into the target's default model first (export/refit.h) and the added error recorded in
// the files and the result.
#include <filesystem>
#include <optional>
#include <vector>

#include "brdfkit/export/export_target.h"
#include "brdfkit/export/provenance.h"
#include "brdfkit/fit/fit_record.h"
#include "brdfkit/models/model.h"

namespace brdfkit::exporter {

struct ExportResult {
  Brdf written;                             // the model and values in the files
  Provenance provenance;
  std::vector<std::filesystem::path> files; // every file written
  double refit_seconds = 0;
};

ExportResult export_fit(const Brdf& fit, const std::optional<fit::FitRecord>& record, Target target,
                        const std::filesystem::path& output);

}  // namespace brdfkit::exporter
