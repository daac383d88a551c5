#include "brdfkit/analysis/model_checks.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <random>

#include "brdfkit/core/sphere_integral.h"

namespace brdfkit {

double ndf_normalization(const std::function<double(double)>& D) {
  using Gk = boost::math::quadrature::gauss_kronrod<double, 15>;
  const auto f = [&](double t) { return D(std::cos(t)) * std::cos(t) * std::sin(t); };
  // Geometric breakpoints: a lobe of width α near θ = 0 always spans a few cells.
  std::vector<double> b = {0.0};
  for (double t = 1e-4; t < kPi / 2; t *= 4) b.push_back(t);
  b.push_back(kPi / 2);
  double sum = 0;
  for (size_t i = 0; i + 1 < b.size(); ++i) sum += Gk::integrate(f, b[i], b[i + 1], 15, 1e-12);
  return 2 * kPi * sum;
}

ReciprocityCheck reciprocity_check(const Model& model, const double* p, int c, int pairs, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double cos_max = std::cos(89.0 * kPi / 180.0);
  auto direction = [&] {
    const double ct = cos_max + (1.0 - cos_max) * u(rng);  // uniform in solid angle
    return spherical_direction(std::acos(ct), 2 * kPi * u(rng));
  };
  ReciprocityCheck r;
  for (int k = 0; k < pairs; ++k) {
    const Vec3d wi = direction(), wo = direction();
    const double a = model.eval(p, c, wi, wo), b = model.eval(p, c, wo, wi);
    const double scale = std::max(std::abs(a), std::abs(b));
    if (scale == 0) continue;
    ++r.pairs;
    const double e = std::isfinite(a) && std::isfinite(b) ? std::abs(a - b) / scale : INFINITY;
    if (e >= r.max_relative_error) {
      r.max_relative_error = e;
      r.wi = wi;
      r.wo = wo;
    }
  }
  return r;
}

double albedo(const BrdfFunction& rho, double theta_i, double rel_tol) {
  const Vec3d wi = spherical_direction(theta_i, 0.0);
  // Integrand over (θo, φo): ρ cosθo sinθo. The mirror direction is (θi, ±π).
  const auto f = [&](double t, double phi) {
    const Vec3d wo = spherical_direction(t, phi);
    return rho(wi, wo) * std::cos(t) * std::sin(t);
  };
  const auto thetas = breakpoints(0.0, kPi / 2, 8, {theta_i});
  const auto phis = breakpoints(-kPi, kPi, 16, {-kPi, 0.0, kPi});
  return integrate_grid(f, thetas, phis, rel_tol, 6);
}

double albedo(const Model& model, const double* p, int c, double theta_i, double rel_tol) {
  return albedo([&](const Vec3d& wi, const Vec3d& wo) { return model.eval(p, c, wi, wo); }, theta_i, rel_tol);
}

std::vector<double> albedo_angles_deg() { return {0, 10, 20, 30, 40, 50, 60, 70, 80}; }

}  // namespace brdfkit
