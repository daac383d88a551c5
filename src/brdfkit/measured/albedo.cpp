#include "brdfkit/measured/albedo.h"

#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <vector>

namespace brdfkit {
namespace {

constexpr unsigned kGaussPoints = 8;

struct Node {
  double x, w;
};

// Composite Gauss–Legendre nodes on [a, b] with `panels` equal panels; Boost stores the
// non-negative abscissae of the rule on [−1, 1] (0 first when the order is odd).
std::vector<Node> composite_gauss(double a, double b, int panels) {
  using Rule = boost::math::quadrature::gauss<double, kGaussPoints>;
  const auto& xs = Rule::abscissa();
  const auto& ws = Rule::weights();
  std::vector<Node> nodes;
  const double h = (b - a) / panels;
  for (int p = 0; p < panels; ++p) {
    const double mid = a + (p + 0.5) * h, half = 0.5 * h;
    for (size_t k = 0; k < xs.size(); ++k) {
      nodes.push_back({mid - half * xs[k], half * ws[k]});
      if (xs[k] != 0) nodes.push_back({mid + half * xs[k], half * ws[k]});
    }
  }
  return nodes;
}

}  // namespace

DirectionalAlbedo directional_albedo(const AlbedoIntegrand& rho, double theta_i, const AlbedoQuadrature& q) {
  const Vec3d wi = spherical_direction(theta_i, 0.0);
  const std::vector<Node> s_nodes = composite_gauss(0, 1, q.s_panels);
  const std::vector<Node> phi_nodes = composite_gauss(0, 2 * kPi, q.phi_panels);
  Rgb sum = Rgb::Zero();
  double covered = 0, missing = 0;  // ∫ cos θo dωo where ρ answered / did not
  for (const Node& s : s_nodes) {
    const double theta_h = (kPi / 2) * s.x * s.x;
    const double jac_s = kPi * s.x * std::sin(theta_h);  // dθh/ds · sin θh
    for (const Node& p : phi_nodes) {
      const Vec3d h = spherical_direction(theta_h, p.x);
      const double wi_h = wi.dot(h);
      if (wi_h <= 0) continue;
      const Vec3d wo = reflect(wi, h);
      if (wo.z() <= 0) continue;
      // cos θo · dωo/dωh (= 4 wi·h) · dωh/(ds dφh) · weights
      const double w = wo.z() * 4 * wi_h * jac_s * s.w * p.w;
      if (const std::optional<Rgb> v = rho(wi, wo)) {
        sum += w * *v;
        covered += w;
      } else {
        missing += w;
      }
    }
  }
  DirectionalAlbedo out;
  out.value = sum;
  out.missing_fraction = covered + missing > 0 ? missing / (covered + missing) : 1.0;
  return out;
}

std::optional<DirectionalAlbedo> directional_albedo(const MeasuredBrdf& brdf, double theta_i,
                                                    const AlbedoQuadrature& q) {
  DirectionalAlbedo a = directional_albedo(
      [&](const Vec3d& wi, const Vec3d& wo) { return brdf.eval(wi, wo); }, theta_i, q);
  if (a.missing_fraction >= 1.0) return std::nullopt;
  return a;
}

}  // namespace brdfkit
