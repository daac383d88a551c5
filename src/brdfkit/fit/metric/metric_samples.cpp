#include "brdfkit/fit/metric/metric_samples.h"

#include <algorithm>
#include <cmath>

namespace brdfkit::fit {

namespace {

constexpr size_t kChunkSize = 4096;
constexpr double kSameTheta = 1e-5;  // radians: θi written with 6 decimals in the files

double theta_of(double z) { return std::acos(std::clamp(z, -1.0, 1.0)); }

}  // namespace

bool is_scattered(const MeasuredBrdf& data) {
  const double deg = kPi / 180;
  for (double ti : {20.0, 45.0, 60.0})
    for (double to : {30.0, 50.0})
      for (double dp : {90.0, 135.0}) {
        const Vec3d wi = spherical_direction(ti * deg, 0.0), wo = spherical_direction(to * deg, dp * deg);
        if (data.eval(wi, wo)) return false;
      }
  return data.samples().size() > 0;
}

SampleDomain build_sample_domain(const SampleSet& s, double (*density)(const Vec3d& wi, const Vec3d& wo),
                                 bool cos_i_factor) {
  std::vector<size_t> keep;
  for (size_t k = 0; k < s.size(); ++k)
    if (s.valid[k] && s.value(k).allFinite() && s.wi_z[k] > 0 && s.wo_z[k] > 0 && s.weight[k] > 0 &&
        std::isfinite(s.weight[k]))
      keep.push_back(k);
  // Distinct incidence angles and their sample counts (pair measure, see the header).
  std::vector<double> thetas;
  for (size_t k : keep) thetas.push_back(theta_of(s.wi_z[k]));
  std::vector<double> rings = thetas;
  std::sort(rings.begin(), rings.end());
  std::vector<double> distinct;
  for (double t : rings)
    if (distinct.empty() || t - distinct.back() > kSameTheta) distinct.push_back(t);
  const bool per_incidence = distinct.size() < keep.size();
  auto incidence_measure = [&](double t) {
    if (!per_incidence) return 1.0;
    const size_t g = size_t(std::lower_bound(distinct.begin(), distinct.end(), t - kSameTheta) - distinct.begin());
    const double lo = g == 0 ? 0.0 : 0.5 * (distinct[g - 1] + distinct[g]);
    const double hi = g + 1 == distinct.size() ? kPi / 2 : 0.5 * (distinct[g] + distinct[g + 1]);
    return 2 * kPi * (std::cos(lo) - std::cos(hi));
  };
  SampleDomain d;
  for (size_t n = 0; n < keep.size(); ++n) {
    const size_t k = keep[n];
    const Vec3d wi = s.wi(k), wo = s.wo(k);
    const double mu = density(wi, wo);
    if (!(mu > 0)) continue;
    const double w = s.weight[k] * incidence_measure(thetas[n]);
    d.measure_sum += w;
    if (d.chunks.empty() || d.chunks.back().size() == kChunkSize) d.chunks.emplace_back();
    MetricChunk& ch = d.chunks.back();
    ch.push(wi, wo, w * mu, cos_i_factor ? wi.z() : 1.0, s.value(k));
  }
  return d;
}

}  // namespace brdfkit::fit
