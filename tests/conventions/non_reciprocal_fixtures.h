#pragma once
// Test-only BRDFs that are NOT reciprocal, so that every place where brdfkit decides which
// direction is which (wi towards the light, wo towards the viewer, DESIGN.md §2) shows a swap:
//   IncidenceOnlyData    measured data m_c(wi, wo) = a_c + b / cosθi, a function of θi alone
//   IncidenceOnlyModel   a model ρ_c(wi, wo) = a_c + (b + k) / cosθi with parameter k, so that
//                        cosθi (ρ − m) = k exactly at every pair
// Both ignore wo entirely: any code that hands them the directions swapped sees θo instead.
#include <array>
#include <optional>
#include <string>

#include "brdfkit/core/warp.h"
#include "brdfkit/measured/measured_brdf.h"
#include "brdfkit/models/model.h"

namespace brdfkit::test {

inline constexpr std::array<double, 3> kIncidenceA = {0.2, 0.12, 0.05};
inline constexpr double kIncidenceB = 0.02;

class IncidenceOnlyData final : public MeasuredBrdf {
 public:
  std::string format() const override { return "test"; }
  std::string path() const override { return "incidence-only"; }
  std::string dimensions() const override { return "analytic"; }
  std::optional<Rgb> eval(const Vec3d& wi, const Vec3d& wo) const override {
    if (!(wi.z() > 0 && wo.z() > 0)) return std::nullopt;
    return Rgb(kIncidenceA[0], kIncidenceA[1], kIncidenceA[2]) + kIncidenceB / wi.z();
  }
  SampleSet samples() const override { return {}; }
};

class IncidenceOnlyModel final : public Model {
 public:
  IncidenceOnlyModel() : table_{{"k", -10.0, 10.0, 0.01, Scope::Shared, false, "cosθi (ρ − m), test only"}} {}
  std::string_view name() const override { return "incidence-only"; }
  std::string_view description() const override { return "test-only non-reciprocal model"; }
  const ParamTable& params() const override { return table_; }
  bool reciprocal() const override { return false; }
  double eval(const double* p, int c, const Vec3d& wi, const Vec3d& wo) const override {
    if (!(wi.z() > 0 && wo.z() > 0)) return 0.0;
    return kIncidenceA[size_t(c)] + (kIncidenceB + p[0]) / wi.z();
  }
  std::optional<Vec3d> sample(const double*, int, const Vec3d&, const Vec2d& u, double) const override {
    return square_to_cosine_hemisphere(u);
  }
  double pdf(const double*, int, const Vec3d&, const Vec3d& wi) const override { return cosine_hemisphere_pdf(wi); }

 private:
  ParamTable table_;
};

}  // namespace brdfkit::test
