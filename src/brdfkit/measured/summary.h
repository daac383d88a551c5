#pragma once
// What `brdfkit info` reports about a measured file: counts, per-channel statistics of the valid
// values and the directional albedo (DESIGN.md §2), computed for any MeasuredBrdf.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdfkit/measured/albedo.h"
#include "brdfkit/measured/measured_brdf.h"

namespace brdfkit {

// Linear sRGB luminance Y (IEC 61966-2-1 / Rec. 709 primaries; the weights of RGL's `luminance`
// table, DESIGN.md §2).
inline double luminance(const Rgb& c) { return 0.212671 * c[0] + 0.715160 * c[1] + 0.072169 * c[2]; }

struct ChannelStats {
  double min = 0, max = 0, mean = 0;  // over valid values, sr⁻¹
  size_t negative = 0;                // valid values < 0 (measurement noise; MERL: always 0)
};

struct AlbedoRow {
  double theta_i = 0;                      // radians
  std::optional<DirectionalAlbedo> albedo;  // nullopt: the data cannot give it at this θi
};

struct MeasuredSummary {
  std::string path, format, dimensions;
  bool isotropic = true;  // MeasuredBrdf::isotropic(): the albedo rows are then at φi = 0
  size_t total = 0;  // cells (tabulated formats) or samples
  size_t valid = 0;  // measured ones
  std::array<ChannelStats, 3> channels{};
  // How the albedo was obtained: "eval" (half-vector quadrature of eval(), measured/albedo.h),
  // "samples" (the format's own albedos_from_samples()) or "none".
  std::string albedo_method;
  std::vector<AlbedoRow> albedo;  // θi = 0°, 10°, …, 80°
  // Maximum over θi ∈ [0°, 80°] (every 5° for "eval"; the data's own θi for "samples"), pooled
  // two ways: per channel independently (each channel's own maximum and where it occurs), and
  // of the luminance Y of the albedo (and where it occurs). Absent when no albedo is available.
  std::optional<Rgb> max_albedo;
  std::array<double, 3> max_albedo_theta_i{};
  std::optional<double> max_luminance;
  double max_luminance_theta_i = 0;
};

// Throws what the BRDF's methods throw; never returns NaN for finite data.
MeasuredSummary summarize(const MeasuredBrdf& brdf, const AlbedoQuadrature& q = {});

// The summary as `brdfkit info --json` and Python's Measured.info() give it (angles in degrees).
nlohmann::json summary_json(const MeasuredSummary& s);

}  // namespace brdfkit
