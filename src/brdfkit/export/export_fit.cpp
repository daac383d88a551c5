#include "brdfkit/export/export_fit.h"

#include "brdfkit/core/atomic_file.h"
#include "brdfkit/export/brdf_explorer.h"
#include "brdfkit/export/glsl_function.h"
#include "brdfkit/export/gltf_material.h"
#include "brdfkit/export/mitsuba_scene.h"
#include "brdfkit/export/pbrt_scene.h"
#include "brdfkit/export/refit.h"

namespace brdfkit::exporter {

ExportResult export_fit(const Brdf& fit, const std::optional<fit::FitRecord>& record, Target target,
                        const std::filesystem::path& output) {
  Provenance p;
  p.target = std::string(target_name(target));
  p.source_model = std::string(fit.model().name());
  p.metric = record && !record->fit_metric.empty() ? record->fit_metric : "ngan";
  if (record) {
    p.data_file = record->data_file;
    p.data_sha256 = record->data_sha256;
    for (const auto& m : record->metrics)
      if (m.id == p.metric && m.value) p.source_error = *m.value;
  }
  ExportResult r{fit, p, {}, 0};
  if (!exports_exactly(target, fit.model(), fit.values())) {
    const RefitResult rf = refit(fit, default_model(target), p.metric);
    r.written = rf.brdf;
    r.provenance.refitted = true;
    r.provenance.added_error = rf.added_error;
    r.refit_seconds = rf.seconds;
  }
  r.provenance.model = std::string(r.written.model().name());
  switch (target) {
    case Target::Gltf: write_gltf(output, r.written, r.provenance); r.files = {output}; break;
    case Target::Mitsuba3: r.files = write_mitsuba(output, r.written, r.provenance); break;
    case Target::PbrtV4: r.files = write_pbrt(output, r.written, r.provenance); break;
    case Target::BrdfExplorer: write_brdf_explorer(output, r.written, r.provenance); r.files = {output}; break;
    case Target::Glsl: write_file_atomically(output, glsl_file(r.written, r.provenance)); r.files = {output}; break;
  }
  return r;
}

}  // namespace brdfkit::exporter
