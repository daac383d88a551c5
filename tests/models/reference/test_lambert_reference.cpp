// Lambertian models: ρ = kd/π (DESIGN.md §6) at every pair (`lambert`, and pbrt-v4's DiffuseBxDF
// as `pbrt-diffuse`, R/π), and the closed-form albedo a(wi) = ∫ ρ cosθo dωo = kd at several
// incidences by Gauss-Legendre quadrature in cosθo (exact for a constant), bound 1e-13.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss.hpp>

#include <cmath>

#include "brdfkit/models/model.h"
#include "reference_pairs.h"

namespace brdfkit::test::ref {
namespace {

double albedo(const Model& m, const ParamValues& v, int c, const Vec3d& wi) {
  const int n_phi = 16;
  double sum = 0;
  for (int k = 0; k < n_phi; ++k) {
    const double phi = (k + 0.5) * 2 * kPi / n_phi;
    sum += boost::math::quadrature::gauss<double, 20>::integrate(
        [&](double mu) {
          const double s = std::sqrt(1 - mu * mu);
          return m.eval(v.channel(c), c, wi, Vec3d(s * std::cos(phi), s * std::sin(phi), mu)) * mu;
        },
        0.0, 1.0);
  }
  return 2 * kPi * sum / n_phi;
}

TEST(LambertReference, ValuesAndAlbedo) {
  for (const char* name : {"lambert", "pbrt-diffuse"}) {
    const Model& m = model_by_name(name);
    const std::string p = m.params()[0].name;  // kd, or pbrt's reflectance
    const ParamValues v = values_of(m, {{p, 0.9, 0}, {p, 0.35, 1}, {p, 0.02, 2}});
    auto reference = [&m, v, p](double norm) -> Reference {
      return [&m, v, p, norm](int c, const Vec3d&, const Vec3d&) { return param(m, v, p, c) / norm; };
    };
    expect_matches_reference(m, v, reference(kPi), 1e-14, p + "/pi");
    expect_detects_five_percent(m, v, reference(kPi / 1.05), 1e-14, p + "/pi");
    for (double theta_deg : {0.0, 35.0, 80.0})
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(albedo(m, v, c, spherical_direction(theta_deg * kPi / 180, 0.3)), param(m, v, p, c), 1e-13)
            << name << " channel " << c << " at " << theta_deg << " deg";
  }
}

}  // namespace
}  // namespace brdfkit::test::ref
