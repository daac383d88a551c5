// Seed 000 §4.5 samples SGD through a GGX proxy; its printed weight
//   w = 4 ρs/p_spec · F D G cos³θm (α² + tan²θm)²/α²  = 4 ρs F D G / (π pdf_ggx(m))
// misses the factor |i·m|/cosθi of the half-vector Jacobian (DESIGN.md §6). With an inline
// Cook-Torrance lobe in the seed's scale, ρ = ρs/π · F D G/(cosθi cosθo), F = G = ρs = 1, the
// corrected weight reproduces the albedo by quadrature and the printed one does not.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <cstdio>
#include <random>

#include "brdfkit/ndf/sgd.h"

namespace brdfkit {
namespace {

TEST(NdfSgdProxy, PrintedWeightBiasesTheAlbedoCorrectedWeightDoesNot) {
  const double params[2] = {0.2, 0.6};
  const Sgd<double> sgd(params);
  const double theta_i = 1.2;
  const Vec3d wi(std::sin(theta_i), 0.0, std::cos(theta_i));

  // Albedo ∫ ρ cosθo dωo = 1/(π cosθi) ∫ D(h) dωo by nested Gauss-Kronrod over (θo, φo);
  // the lobe is symmetric about the plane of incidence, so φo ∈ [0, π] doubled.
  using boost::math::quadrature::gauss_kronrod;
  const double inner_tol = 1e-9;
  const double quad = 2.0 / (kPi * wi.z()) * gauss_kronrod<double, 31>::integrate(
      [&](double to) {
        return std::sin(to) * gauss_kronrod<double, 31>::integrate(
                                  [&](double po) {
                                    const Vec3d wo(std::sin(to) * std::cos(po), std::sin(to) * std::sin(po), std::cos(to));
                                    return sgd.D((wi + wo).normalized().z());
                                  },
                                  0.0, kPi, 10, inner_tol);
      },
      0.0, kPi / 2, 10, 1e-9);

  std::mt19937_64 rng(20121);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  const long n = 200000;
  double sp = 0, sp2 = 0, sc = 0, sc2 = 0;
  for (long k = 0; k < n; ++k) {
    double w = 0;  // D_sgd/D_ggx
    const Vec3d m = sgd.sample_ggx_proxy(Vec2d(uni(rng), uni(rng)), &w);
    const double im = wi.dot(m);
    const Vec3d wo = 2 * std::abs(im) * m - wi;  // o = 2|i·m| m − i (seed 000 §4.5)
    if (!(wo.z() > 0.0) || !(im > 0.0)) continue;
    const double d_over_pdf = w / m.z();  // D_sgd(m)/pdf_ggx(m), pdf_ggx = D_ggx cosθm
    const double printed = 4.0 / kPi * d_over_pdf;
    const double corrected = printed * im / wi.z();
    sp += printed, sp2 += printed * printed, sc += corrected, sc2 += corrected * corrected;
  }
  const double mp = sp / n, ep = std::sqrt((sp2 / n - mp * mp) / n);
  const double mc = sc / n, ec = std::sqrt((sc2 / n - mc * mc) / n);
  std::printf("[ albedo   ] SGD alpha 0.2, p 0.6, theta_i 1.2: quadrature %.4f, corrected weight %.4f +- %.4f, printed weight %.4f +- %.4f\n",
              quad, mc, ec, mp, ep);
  EXPECT_NEAR(mc, quad, 4 * ec);
  EXPECT_GT(std::abs(mp - quad), 20 * ep);
  EXPECT_LT(mp, 0.9 * quad);  // the printed weight loses ~16% here
}

}  // namespace
}  // namespace brdfkit
