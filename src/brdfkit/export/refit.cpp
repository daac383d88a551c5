#include "brdfkit/export/refit.h"

#include <chrono>

#include <fmt/format.h>

#include "brdfkit/fit/fit_job.h"
#include "brdfkit/fit/metric/metric_report.h"
#include "brdfkit/measured/merl_brdf.h"
#include "brdfkit/measured/merl_tabulate.h"

namespace brdfkit::exporter {

RefitResult refit(const Brdf& source, const Model& target, const std::string& metric, int starts) {
  const auto t0 = std::chrono::steady_clock::now();
  const MerlBrdf table(merl::tabulate([&](const Vec3d& wi, const Vec3d& wo) { return source.eval(wi, wo); }),
                       fmt::format("({} tabulated on the MERL grid)", source.model().name()));
  fit::FitSettings settings;
  settings.metric = metric.empty() ? "ngan" : metric;
  settings.starts = starts;
  fit::MetricStore store(table);
  const fit::FitJobResult r = fit::run_fit_job(target, store, table.path(), "", settings);
  const auto report = fit::report_metrics(store, target, r.record.values, {settings.metric}, fit::MetricOptions{});
  const double added = report.empty() || !report.front().value ? r.fit.metric_value : *report.front().value;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {Brdf(target, r.record.values), settings.metric, added, seconds};
}

}  // namespace brdfkit::exporter
