#pragma once
// Directional albedo a(θi) = ∫ ρ(wi, wo) cos θo dωo (DESIGN.md §2) of any BRDF given as a callable
// or as a MeasuredBrdf that answers eval().
//
// Quadrature (documented choice): integrate over the half vector h instead of wo, since measured
// and microfacet lobes are compact in h. wo = reflect(wi, h) and dωo = 4 |wi·h| dωh (the Jacobian
// ‖∂ωo/∂ωm‖ of seed 000's importance-sampling weight, after Walter et al. 2007), with h on the
// upper hemisphere and wi·h > 0, which reaches every wo above the horizon exactly once; h whose
// wo falls below the horizon are rejected. θh = (π/2) s², dθh = π s ds, concentrates the nodes near the specular peak as MERL's
// own θh axis does. In s ∈ [0, 1] and φh ∈ [0, 2π): composite Gauss–Legendre
// (boost::math::quadrature::gauss, 8 points per panel), panels equal in s and in φh.
// Where ρ has no value (nullopt: not measured) the node is skipped and its share of
// ∫ cos θo dωo is reported as missing_fraction (the albedo is then not extrapolated).
#include <functional>
#include <optional>

#include "brdfkit/core/vec.h"
#include "brdfkit/measured/measured_brdf.h"

namespace brdfkit {

struct DirectionalAlbedo {
  Rgb value = Rgb::Zero();      // per channel
  double missing_fraction = 0;  // of ∫ cos θo dωo = π where ρ had no value, in [0, 1]
};

struct AlbedoQuadrature {
  // 8-point Gauss–Legendre panels in s and in φh. The defaults give a tabulated Lambertian
  // 0.5/π as 0.500 ± 0.005 at θi ≤ 80° and a tabulated GGX (α = 0.3) within 1 % of the analytic
  // integral (tests/measured/test_albedo.cpp).
  int s_panels = 16;
  int phi_panels = 16;
};

using AlbedoIntegrand = std::function<std::optional<Rgb>(const Vec3d& wi, const Vec3d& wo)>;

// a(θi) for wi = (sin θi, 0, cos θi), θi in radians, in [0, π/2).
DirectionalAlbedo directional_albedo(const AlbedoIntegrand& rho, double theta_i, const AlbedoQuadrature& q = {});
// Through brdf.eval(); nullopt when eval() answered at no node (scattered or slice data).
std::optional<DirectionalAlbedo> directional_albedo(const MeasuredBrdf& brdf, double theta_i,
                                                    const AlbedoQuadrature& q = {});

}  // namespace brdfkit
