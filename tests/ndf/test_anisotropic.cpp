// The anisotropic distributions (ndf/ggx_anisotropic.h, ndf/beckmann_anisotropic.h): equal to the
// isotropic ones at αx = αy; normalized; their Λ is Smith's Λ of their own D, i.e. the projected
// area ∫ D(m) max(0, w·m) dω = (1 + Λ(w)) cosθw (Heitz 2014, the microfacet projected-area
// identity with Smith's masking), by a quadrature over the slope plane that uses only D.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>

#include "brdfkit/core/vec.h"
#include "brdfkit/ndf/beckmann.h"
#include "brdfkit/ndf/beckmann_anisotropic.h"
#include "brdfkit/ndf/ggx.h"
#include "brdfkit/ndf/ggx_anisotropic.h"
#include "brdfkit/shadowing/smith.h"

namespace brdfkit {
namespace {

using boost::math::quadrature::gauss_kronrod;

// ∫ D(m) max(0, w·m) dω over the upper hemisphere, as an integral over slopes s = (αx r cosψ,
// αy r sinψ), m = (−s, 1)/|(−s, 1)|, dω = cos³θm d²s. The kink of max(0, ·) is a radius r*(ψ) per
// ψ: the inner integral ends there. r = t/(1 − t) maps [0, ∞) to [0, 1).
template <class Ndf>
double projected_area(const Ndf& d, const Vec3d& w, double ax, double ay) {
  auto inner = [&](double psi) {
    const double cx = ax * std::cos(psi), cy = ay * std::sin(psi);
    const double k = w.x() * cx + w.y() * cy;  // w·(−s, 1)/(1 · r) slope term
    const double t_max = k > 0 ? (w.z() / k) / (1 + w.z() / k) : 1.0;
    return gauss_kronrod<double, 31>::integrate(
        [&](double t) {
          if (t >= 1) return 0.0;
          const double r = t / (1 - t), jac = 1 / ((1 - t) * (1 - t));
          const Vec3d u(-r * cx, -r * cy, 1.0);
          const double len = u.norm(), c = 1 / len;
          const Vec3d m = u / len;
          return d.D(m) * std::max(0.0, w.dot(m)) * c * c * c * ax * ay * r * jac;
        },
        0.0, t_max, 12, 1e-11);
  };
  return gauss_kronrod<double, 61>::integrate(inner, 0.0, 2 * kPi, 12, 1e-10);
}

template <template <class> class Aniso>
void expect_smith_consistent(double ax, double ay) {
  const double p[] = {ax, ay};
  const Aniso<double> d(p);
  EXPECT_NEAR(projected_area(d, Vec3d(0, 0, 1), ax, ay), 1.0, 1e-7) << ax << " " << ay;  // normalization
  for (double theta : {0.3, 0.9, 1.3})
    for (double phi : {0.0, 0.8, 2.0, 4.0}) {
      const Vec3d w(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      EXPECT_NEAR(projected_area(d, w, ax, ay), (1 + d.Lambda(w)) * w.z(), 1e-7 * (1 + d.Lambda(w)))
          << Aniso<double>::kName << " " << ax << " " << ay << " θ " << theta << " φ " << phi;
    }
}

TEST(AnisotropicNdf, LambdaIsSmithsLambdaOfTheirOwnDistribution) {
  expect_smith_consistent<GgxAnisotropic>(0.1, 0.4);
  expect_smith_consistent<GgxAnisotropic>(0.5, 0.15);
  expect_smith_consistent<BeckmannAnisotropic>(0.1, 0.4);
  expect_smith_consistent<BeckmannAnisotropic>(0.6, 0.2);
}

TEST(AnisotropicNdf, EqualWidthsAreTheIsotropicDistributions) {
  for (double a : {0.05, 0.3, 1.1}) {
    const double p2[] = {a, a};
    const GgxAnisotropic<double> ga(p2);
    const BeckmannAnisotropic<double> ba(p2);
    const Ggx<double> g(&a);
    const Beckmann<double> b(&a);
    for (double theta : {0.0, 0.2, 0.7, 1.2, 1.5})
      for (double phi : {0.0, 1.0, 2.5}) {
        const Vec3d w(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
        EXPECT_NEAR(ga.D(w), g.D(w.z()), 1e-12 * g.D(w.z())) << a << " " << theta;
        EXPECT_NEAR(ba.D(w), b.D(w.z()), 1e-12 * b.D(w.z()) + 1e-300) << a << " " << theta;
        EXPECT_NEAR(ga.Lambda(w), g.Lambda(std::tan(theta)), 1e-12 * (1 + g.Lambda(std::tan(theta))))
            << a << " " << theta;
        EXPECT_NEAR(ba.Lambda(w), b.Lambda(std::tan(theta)), 1e-12 * (1 + b.Lambda(std::tan(theta))))
            << a << " " << theta;
      }
  }
}

}  // namespace
}  // namespace brdfkit
