#pragma once
// Cook-Torrance with a tabulated distribution estimated from data (seed 002 §5.1, DESIGN.md §3, §6):
//   ρ(wi, wo) = kd/π + ks F(θd) D(θh) G1(θi) G1(θo) / (4 cosθi cosθo),
// F = Schlick, D = ndf/tabulated.h, G1 = Smith masking of that D through the projected-area
// identity (projected_area_masking.h; the g(k) = ⟨k·h⟩ of seed 002 Eq. 3).
//
// The table is data, not parameters, so this is a runtime Model built per table (it is not in
// the static catalogue of models/registry.cpp): it evaluates, samples and is scored by the
// metric code like any model; its parameters are kd, ks (per channel, linear) and F0 (per channel).
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdfkit/analysis/projected_area_masking.h"
#include "brdfkit/models/microfacet_model.h"
#include "brdfkit/models/model.h"
#include "brdfkit/ndf/tabulated.h"

namespace brdfkit::analysis {

class TabulatedCookTorrance final : public Model, public MicrofacetDistributionView {
 public:
  static constexpr std::string_view kName = "cook-torrance-tabulated";
  // D at the angles `theta` (radians, increasing, within [0, π/2]); rescaled to ∫ D cosθ dω = 1.
  // Throws InputError for an invalid table (ndf/tabulated.h).
  TabulatedCookTorrance(std::vector<double> theta, std::vector<double> d);

  std::string_view name() const override { return kName; }
  std::string_view description() const override;
  const ParamTable& params() const override { return table_; }
  bool reciprocal() const override { return true; }
  double eval(const double* p, int c, const Vec3d& wi, const Vec3d& wo) const override;
  std::optional<Vec3d> sample(const double* p, int c, const Vec3d& wo, const Vec2d& u, double u_lobe) const override;
  double pdf(const double* p, int c, const Vec3d& wo, const Vec3d& wi) const override;
  double ndf(const double*, double cos_theta_h) const override { return ndf_.D(cos_theta_h); }

  const Tabulated<double>& distribution() const { return ndf_; }
  const ProjectedAreaMasking& masking() const { return masking_; }
  // The specular factor without ks and F: D(θh) G1(θi) G1(θo) / (4 cosθi cosθo).
  double specular_shape(const Vec3d& wi, const Vec3d& wo) const;

  // {"theta": [...], "D": [...]} (radians; normalized D) and back (InputError naming `where`).
  nlohmann::json table_json() const;
  static TabulatedCookTorrance from_table_json(const nlohmann::json& j, const std::string& where);

 private:
  ParamTable table_;
  Tabulated<double> ndf_;
  ProjectedAreaMasking masking_;
};

}  // namespace brdfkit::analysis
