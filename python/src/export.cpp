// brdfkit.export(fit, to, output): a fit written for a renderer as `brdfkit export` writes it.
#include <pybind11/stl.h>

#include "brdfkit/export/export_fit.h"
#include "brdfkit/fit/fit_record.h"
#include "python_api.h"

namespace brdfkit::python {

void bind_export(py::module_& m) {
  m.def("_export", [](const Brdf& brdf, const std::optional<std::string>& record_json, const std::string& to,
                      const std::string& output) {
    std::optional<fit::FitRecord> record;
    if (record_json) record = fit::fit_record_from_json(nlohmann::json::parse(*record_json), "fit");
    const exporter::Target target = exporter::parse_target(to, "to");
    std::optional<exporter::ExportResult> r;
    {
      py::gil_scoped_release release;
      r.emplace(exporter::export_fit(brdf, record, target, output));
    }
    py::dict out;
    std::vector<std::string> files;
    for (const auto& f : r->files) files.push_back(f.string());
    out["files"] = files;
    out["written"] = r->written;
    out["provenance"] = to_python(exporter::provenance_json(r->provenance));
    out["refit_seconds"] = r->refit_seconds;
    return out;
  });
}

}  // namespace brdfkit::python
