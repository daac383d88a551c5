#pragma once
// Numerical checks every model must pass (DESIGN.md §3, §6): normalization of its microfacet
// distribution, reciprocity, and albedo (directional-hemispherical reflectance).
#include <cstdint>
#include <functional>
#include <vector>

#include "brdfkit/core/vec.h"
#include "brdfkit/models/model.h"

namespace brdfkit {

// ∫ D(ωm) cosθm dωm = 2π ∫₀^{π/2} D(cosθ) cosθ sinθ dθ for D given as a function of cosθ
// (DESIGN.md §3: 1 for every normalized distribution). Breakpoints at θ = 10⁻⁴·4ᵏ resolve
// peaks down to α ≈ 10⁻³.
double ndf_normalization(const std::function<double(double cos_theta)>& D);

struct ReciprocityCheck {
  double max_relative_error = 0;  // max |ρ(wi,wo) − ρ(wo,wi)| / max(|ρ(wi,wo)|, |ρ(wo,wi)|)
  Vec3d wi = Vec3d::UnitZ(), wo = Vec3d::UnitZ();  // the worst pair
  int pairs = 0;                  // pairs compared (both values zero are skipped)
};
// Over `pairs` direction pairs drawn uniformly on the hemisphere (θ < 89°), seeded.
ReciprocityCheck reciprocity_check(const Model& model, const double* p, int c, int pairs = 2000,
                                   std::uint64_t seed = 20120501);

using BrdfFunction = std::function<double(const Vec3d& wi, const Vec3d& wo)>;

// a(wi) = ∫ ρ(wi, wo) cosθo dωo (DESIGN.md §2) for wi at polar angle theta_i in the φ = 0 plane,
// by adaptive Gauss–Kronrod over (θo, φo) with fine cells around the mirror direction. The
// tolerance is per 1-D pass; tabulated Smith Λ (C¹ Catmull-Rom) slows convergence below ~1e-6,
// so the default stops there (results agree with 1e-9 runs to ~1e-6 on smooth models).
double albedo(const BrdfFunction& rho, double theta_i, double rel_tol = 1e-5);
double albedo(const Model& model, const double* p, int c, double theta_i, double rel_tol = 1e-5);

// Albedo at θi = 0°, 10°, …, 80° (the angles `brdfkit check` prints).
std::vector<double> albedo_angles_deg();

}  // namespace brdfkit
