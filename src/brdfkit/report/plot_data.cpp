#include "brdfkit/report/plot_data.h"

#include <cmath>

#include "brdfkit/core/half_diff.h"
#include "brdfkit/measured/albedo.h"
#include "brdfkit/measured/summary.h"

namespace brdfkit::report {
namespace {

constexpr double kDeg = kPi / 180;
const double kSliceAngles[4] = {0, 30, 60, 75};

// wo in the incidence plane of wi = (sin θi, 0, cos θi) at signed angle t: t > 0 on the mirror side.
Vec3d plane_direction(double t_deg) { return Vec3d(-std::sin(t_deg * kDeg), 0, std::cos(t_deg * kDeg)); }

nlohmann::json curve(const std::function<std::optional<Rgb>(const Vec3d&, const Vec3d&)>& rho, double theta_i) {
  const Vec3d wi = spherical_direction(theta_i * kDeg, 0.0);
  nlohmann::json points = nlohmann::json::array();
  for (int t = -89; t <= 89; ++t) {
    const Vec3d wo = plane_direction(t);
    if (const std::optional<Rgb> v = rho(wi, wo)) points.push_back({t, luminance(*v) * wo.z()});
  }
  return points;
}

// Samples of scattered data near the slice: θi within 1°, wo within 4° of the incidence plane.
nlohmann::json slice_samples(const SampleSet& s, double theta_i) {
  nlohmann::json points = nlohmann::json::array();
  for (size_t k = 0; k < s.size(); ++k) {
    if (!s.valid[k] || std::abs(std::acos(s.wi_z[k]) - theta_i * kDeg) > 1 * kDeg) continue;
    const Vec3d wi = s.wi(k), wo = s.wo(k);
    const double phi = std::atan2(wo.y(), wo.x()) - std::atan2(wi.y(), wi.x());
    if (std::abs(std::sin(phi)) > std::sin(4 * kDeg)) continue;
    const double t = std::acos(wo.z()) / kDeg * (std::cos(phi) < 0 ? 1 : -1);
    points.push_back({t, luminance(s.value(k)) * wo.z()});
  }
  return points;
}

std::optional<Rgb> model_value(const Brdf& b, const Vec3d& wi, const Vec3d& wo) { return b.eval(wi, wo); }

}  // namespace

bool answers_eval(const MeasuredBrdf& data) {
  return data.eval(spherical_direction(0.3, 0.0), spherical_direction(0.3, kPi)).has_value();
}

nlohmann::json incidence_slices(const MeasuredBrdf& data, const std::vector<NamedBrdf>& fits) {
  const bool tabulated = answers_eval(data);
  const SampleSet samples = tabulated ? SampleSet{} : data.samples();
  nlohmann::json out = {{"theta_i_deg", kSliceAngles}, {"slices", nlohmann::json::array()}};
  for (double ti : kSliceAngles) {
    nlohmann::json slice = {{"theta_i_deg", ti}};
    slice["data"] = tabulated ? curve([&](const Vec3d& a, const Vec3d& b) { return data.eval(a, b); }, ti)
                              : slice_samples(samples, ti);
    slice["data_kind"] = slice["data"].empty() ? "none" : tabulated ? "curve" : "samples";
    for (const NamedBrdf& f : fits)
      slice["fits"][f.name] = curve([&](const Vec3d& a, const Vec3d& b) { return model_value(f.brdf, a, b); }, ti);
    out["slices"].push_back(slice);
  }
  return out;
}

nlohmann::json half_diff_maps(const MeasuredBrdf& data, const NamedBrdf& fit, size_t max_samples) {
  constexpr int kBins = 45;
  const SampleSet s = data.samples();
  std::vector<double> sum_data(kBins * kBins, 0), sum_fit(kBins * kBins, 0);
  std::vector<int> count(kBins * kBins, 0);
  const size_t stride = std::max<size_t>(1, s.size() / max_samples);
  for (size_t k = 0; k < s.size(); k += stride) {
    const Vec3d wi = s.wi(k), wo = s.wo(k);
    if (!s.valid[k] || wi.z() < std::cos(85 * kDeg) || wo.z() < std::cos(85 * kDeg)) continue;
    const HalfDiff hd = to_half_diff(wi, wo);
    const int ih = std::min(kBins - 1, int(hd.theta_h / kDeg / 2)), id = std::min(kBins - 1, int(hd.theta_d / kDeg / 2));
    const int cell = ih * kBins + id;
    sum_data[cell] += luminance(s.value(k));
    sum_fit[cell] += luminance(fit.brdf.eval(wi, wo));
    ++count[cell];
  }
  nlohmann::json d = nlohmann::json::array(), f = nlohmann::json::array(), r = nlohmann::json::array();
  for (int ih = 0; ih < kBins; ++ih)
    for (int id = 0; id < kBins; ++id) {
      const int cell = ih * kBins + id;
      if (!count[cell]) continue;
      const double md = sum_data[cell] / count[cell], mf = sum_fit[cell] / count[cell];
      if (md > 0) d.push_back({id, ih, std::log10(md)});
      if (mf > 0) f.push_back({id, ih, std::log10(mf)});
      if (md > 0 && mf > 0) r.push_back({id, ih, std::log2(md / mf)});
    }
  return {{"bin_deg", 2}, {"bins", kBins}, {"fit", fit.name}, {"data", d}, {"fit_map", f}, {"log2_ratio", r}};
}

nlohmann::json albedo_curves(const MeasuredBrdf& data, const std::vector<NamedBrdf>& fits) {
  std::vector<int> angles;
  for (int t = 0; t <= 85; t += 5) angles.push_back(t);
  nlohmann::json out = {{"theta_i_deg", angles}, {"data", nlohmann::json::array()}};
  const auto from_samples = data.albedos_from_samples();
  for (int t : angles) {
    const auto a = from_samples.empty() ? directional_albedo(data, t * kDeg) : std::nullopt;
    out["data"].push_back(a ? nlohmann::json(luminance(a->value)) : nlohmann::json());
  }
  if (!from_samples.empty()) {
    out["data_samples"] = nlohmann::json::array();  // the format's own albedo at the θi it holds
    for (const auto& [theta, value] : from_samples) out["data_samples"].push_back({theta / kDeg, luminance(value)});
  }
  for (const NamedBrdf& f : fits) {
    nlohmann::json ys = nlohmann::json::array();
    for (int t : angles)
      ys.push_back(luminance(directional_albedo([&](const Vec3d& wi, const Vec3d& wo) { return model_value(f.brdf, wi, wo); },
                                                t * kDeg)
                                 .value));
    out["fits"][f.name] = ys;
  }
  return out;
}

}  // namespace brdfkit::report
