#include "brdfkit/measured/summary.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "brdfkit/measured/merl_brdf.h"

namespace brdfkit {
namespace {

constexpr double kDeg = kPi / 180;

// Accumulates min/max/mean/negatives of the valid values of one channel.
struct StatsAccumulator {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity(), sum = 0;
  size_t n = 0, negative = 0;
  void add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    sum += v;
    ++n;
    negative += v < 0;
  }
  ChannelStats result() const {
    if (n == 0) return {};
    return {lo, hi, sum / double(n), negative};
  }
};

void fill_counts_and_stats(const MeasuredBrdf& brdf, MeasuredSummary& s) {
  std::array<StatsAccumulator, 3> acc;
  if (const merl::Table* table = brdf.merl_cells()) {
    // The table itself: samples() would list only the valid cells, and costs directions.
    const merl::Table& t = *table;
    s.total = merl::kCellCount;
    for (size_t k = 0; k < merl::kCellCount; ++k) {
      if (!t.valid(k)) continue;
      ++s.valid;
      const Rgb v = t.value(k);
      for (int c = 0; c < 3; ++c) acc[size_t(c)].add(v[c]);
    }
  } else {
    const SampleSet samples = brdf.samples();
    s.total = samples.size();
    for (size_t k = 0; k < samples.size(); ++k) {
      if (!samples.valid[k]) continue;
      ++s.valid;
      for (size_t c = 0; c < 3; ++c) acc[c].add(samples.rgb[c][k]);
    }
  }
  for (size_t c = 0; c < 3; ++c) s.channels[c] = acc[c].result();
}

// Max per channel and of the luminance over (θi, albedo) pairs.
void fill_maxima(const std::vector<std::pair<double, Rgb>>& curve, MeasuredSummary& s) {
  if (curve.empty()) return;
  Rgb best = Rgb::Constant(-std::numeric_limits<double>::infinity());
  double best_y = -std::numeric_limits<double>::infinity();
  for (const auto& [theta, a] : curve) {
    for (int c = 0; c < 3; ++c)
      if (a[c] > best[c]) {
        best[c] = a[c];
        s.max_albedo_theta_i[size_t(c)] = theta;
      }
    if (luminance(a) > best_y) {
      best_y = luminance(a);
      s.max_luminance_theta_i = theta;
    }
  }
  s.max_albedo = best;
  s.max_luminance = best_y;
}

}  // namespace

MeasuredSummary summarize(const MeasuredBrdf& brdf, const AlbedoQuadrature& q) {
  MeasuredSummary s;
  s.path = brdf.path();
  s.format = brdf.format();
  s.dimensions = brdf.dimensions();
  s.isotropic = brdf.isotropic();
  fill_counts_and_stats(brdf, s);

  for (int deg = 0; deg <= 80; deg += 10) s.albedo.push_back({deg * kDeg, std::nullopt});

  if (const auto from_samples = brdf.albedos_from_samples(); !from_samples.empty()) {
    s.albedo_method = "samples";
    std::vector<std::pair<double, Rgb>> curve;
    for (const auto& [theta, a] : from_samples) {
      if (theta <= 80 * kDeg + 1e-6) curve.emplace_back(theta, a);
      for (AlbedoRow& row : s.albedo)
        if (std::abs(row.theta_i - theta) < 0.5 * kDeg) row.albedo = DirectionalAlbedo{a, 0.0};
    }
    fill_maxima(curve, s);
    return s;
  }

  // Quadrature of eval() on a 5° grid: the 10° rows are its even entries.
  constexpr int kSteps = 17;  // 0°, 5°, …, 80°
  std::vector<std::optional<DirectionalAlbedo>> grid(kSteps);
  tbb::parallel_for(0, kSteps, [&](int k) { grid[size_t(k)] = directional_albedo(brdf, 5 * k * kDeg, q); });
  std::vector<std::pair<double, Rgb>> curve;
  for (int k = 0; k < kSteps; ++k) {
    if (!grid[size_t(k)]) continue;
    curve.emplace_back(5 * k * kDeg, grid[size_t(k)]->value);
    if (k % 2 == 0) s.albedo[size_t(k / 2)].albedo = grid[size_t(k)];
  }
  s.albedo_method = curve.empty() ? "none" : "eval";
  fill_maxima(curve, s);
  return s;
}

namespace {

nlohmann::json rgb_json(const Rgb& c) { return nlohmann::json::array({c[0], c[1], c[2]}); }

}  // namespace

nlohmann::json summary_json(const MeasuredSummary& s) {
  nlohmann::json j;
  j["path"] = s.path;
  j["format"] = s.format;
  j["dimensions"] = s.dimensions;
  j["isotropic"] = s.isotropic;
  j["total"] = s.total;
  j["valid"] = s.valid;
  j["valid_fraction"] = s.total ? double(s.valid) / double(s.total) : 0.0;
  nlohmann::json ch = nlohmann::json::object();
  const char* names[3] = {"R", "G", "B"};
  for (size_t c = 0; c < 3; ++c)
    ch[names[c]] = {{"min", s.channels[c].min},
                    {"max", s.channels[c].max},
                    {"mean", s.channels[c].mean},
                    {"negative", s.channels[c].negative}};
  j["channels"] = ch;
  j["albedo_method"] = s.albedo_method;
  nlohmann::json rows = nlohmann::json::array();
  for (const AlbedoRow& r : s.albedo) {
    nlohmann::json row = {{"theta_i_deg", r.theta_i / kDeg}};
    if (r.albedo) {
      row["rgb"] = rgb_json(r.albedo->value);
      row["luminance"] = luminance(r.albedo->value);
      row["missing_fraction"] = r.albedo->missing_fraction;
    } else {
      row["rgb"] = nullptr;
    }
    rows.push_back(row);
  }
  j["albedo"] = rows;
  if (s.max_albedo) {
    j["max_albedo"] = {{"pooling", "per channel: each channel's maximum over theta_i in [0, 80] deg; luminance: "
                                   "maximum of Y = 0.212671 R + 0.715160 G + 0.072169 B"},
                       {"rgb", rgb_json(*s.max_albedo)},
                       {"rgb_theta_i_deg",
                        {s.max_albedo_theta_i[0] / kDeg, s.max_albedo_theta_i[1] / kDeg, s.max_albedo_theta_i[2] / kDeg}},
                       {"luminance", *s.max_luminance},
                       {"luminance_theta_i_deg", s.max_luminance_theta_i / kDeg}};
  } else {
    j["max_albedo"] = nullptr;
  }
  return j;
}

}  // namespace brdfkit
