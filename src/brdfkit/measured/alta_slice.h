#pragma once
// ALTA text slice of a MERL measurement at θd = 0 (`#DIM 1 3`, `#PARAM_IN COS_TH`,
// `#PARAM_OUT RGB_COLOR`, then rows cos θh  R G B): ρ along the retro-reflection/mirror line wi = wo.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "brdfkit/measured/measured_brdf.h"

namespace brdfkit {

class AltaSlice final : public MeasuredBrdf {
 public:
  explicit AltaSlice(const std::filesystem::path& file);

  std::string format() const override { return "alta"; }
  std::string path() const override { return path_; }
  std::string dimensions() const override;
  // Answers only on the slice: wi = wo (within 1e-9), θh = θi, linear interpolation in cos θh
  // between rows (held constant past the end rows); nullopt elsewhere.
  std::optional<Rgb> eval(const Vec3d& wi, const Vec3d& wo) const override;
  // Rows as direction pairs wi = wo = (θh, φ = 0); weight = the row's share of the solid angle of
  // the hemisphere of half vectors, 2π·Δ(cos θh) (midpoint bands between rows).
  SampleSet samples() const override;

  const std::vector<double>& cos_theta_h() const { return cos_th_; }
  const std::vector<Rgb>& values() const { return rgb_; }

 private:
  std::string path_;
  std::vector<double> cos_th_;  // ascending
  std::vector<Rgb> rgb_;
};

std::unique_ptr<MeasuredBrdf> read_alta_slice(const std::filesystem::path& file);

}  // namespace brdfkit
