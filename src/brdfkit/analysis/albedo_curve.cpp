#include "brdfkit/analysis/albedo_curve.h"

#include <cmath>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/albedo.h"

namespace brdfkit::analysis {

AlbedoCurve albedo_curve(const MeasuredBrdf& data, const Model* model, const ParamValues* values,
                         const AlbedoCurveOptions& opt) {
  if (!(opt.step_deg > 0) || !(opt.from_deg >= 0) || !(opt.to_deg < 90) || !(opt.from_deg <= opt.to_deg))
    throw InputError("albedo curve", "need 0 <= from <= to < 90 degrees and step > 0");
  if (model && !values) throw InputError("albedo curve", "a model needs parameter values");
  AlbedoCurve out;
  const auto given = data.albedos_from_samples();
  std::vector<double> angles;
  if (!given.empty()) {
    for (const auto& [t, a] : given) angles.push_back(t * 180 / kPi);
  } else {
    for (double d = opt.from_deg; d <= opt.to_deg + 1e-9; d += opt.step_deg) angles.push_back(d);
  }
  bool any = false;
  for (size_t k = 0; k < angles.size(); ++k) {
    const double ti = angles[k] * kPi / 180;
    out.theta_i_deg.push_back(angles[k]);
    if (!given.empty()) {
      out.data.push_back(given[k].second);
      out.missing_fraction.push_back(0.0);
      any = true;
    } else {
      const auto a = directional_albedo(data, ti);
      out.data.push_back(a ? std::optional<Rgb>(a->value) : std::nullopt);
      out.missing_fraction.push_back(a ? a->missing_fraction : 1.0);
      any = any || a.has_value();
    }
    if (model) {
      const Brdf brdf(*model, *values);
      const auto a = directional_albedo([&](const Vec3d& wi, const Vec3d& wo) -> std::optional<Rgb> { return brdf.eval(wi, wo); }, ti);
      out.model.push_back(a.value);
    } else {
      out.model.push_back(std::nullopt);
    }
  }
  if (!any && !model)
    throw InputError(data.path(), "the data answer no albedo (a slice?) and no model was given");
  return out;
}

}  // namespace brdfkit::analysis
