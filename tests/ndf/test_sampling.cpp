// χ² goodness of fit of every distribution's sampler against D(m) cosθm (DESIGN.md §6), and the
// same test failing when the pdf is scaled or the sampler's parameter is perturbed (so the test
// can fail). Bins in (θ, φ), expected counts by quadrature of the pdf (ndf_test_util.h).
#include <gtest/gtest.h>

#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <cstdio>
#include <vector>

#include "support/all_ndfs.h"
#include "support/ndf_test_util.h"

namespace brdfkit {
namespace {

using test::chi2_theta_phi;

constexpr long kSamples = 100000;

template <class Dist> double chi2_p(const Dist& sampler, const Dist& density, long n = kSamples, double pdf_scale = 1.0) {
  const auto r = chi2_theta_phi([&](const Vec2d& u) { return sampler.sample(u); },
                                [&](double c) { return pdf_scale * density.pdf(Vec3d(std::sqrt(std::max(0.0, 1 - c * c)), 0, c)); }, n);
  return r.p_value;
}

// Passes at p, fails with the pdf scaled by 1.1, fails with parameter `perturb` scaled by `factor`
// (a broad or scale-free lobe needs more than 5% to show with 1e5 samples).
template <template <class> class N>
void expect_sampler(std::vector<double> p, int perturb = 0, long n = kSamples, double factor = 1.05) {
  const std::string name = test::describe_params(p);
  const N<double> d(p.data());
  const double ok = chi2_p(d, d, n);
  EXPECT_GT(ok, 0.01) << name;
  EXPECT_LT(chi2_p(d, d, n, 1.1), 1e-6) << name << " (pdf scaled by 1.1 must fail)";
  std::vector<double> q = p;
  q[perturb] *= factor;
  const N<double> off(q.data());
  EXPECT_LT(chi2_p(off, d, n), 1e-4) << name << " (sampler parameter " << perturb << " x" << factor << " must fail)";
  std::printf("[ chi2     ] %s p = %.4f\n", name.c_str(), ok);
}

TEST(NdfSampling, Beckmann) {
  expect_sampler<Beckmann>({0.005});
  expect_sampler<Beckmann>({0.3});
  expect_sampler<Beckmann>({0.9});
}
TEST(NdfSampling, Ggx) {
  expect_sampler<Ggx>({0.005});
  expect_sampler<Ggx>({0.3});
  expect_sampler<Ggx>({0.9});
}
TEST(NdfSampling, BlinnPhong) {
  expect_sampler<BlinnPhong>({2.0});
  expect_sampler<BlinnPhong>({500.0});
  expect_sampler<BlinnPhong>({5e4});
}
TEST(NdfSampling, GaussianByTabulatedCdf) {
  expect_sampler<Gaussian>({0.005});
  expect_sampler<Gaussian>({0.2});
  expect_sampler<Gaussian>({1.0});
}
TEST(NdfSampling, Exponential) {
  expect_sampler<Exponential>({0.01});
  expect_sampler<Exponential>({0.5});
}
TEST(NdfSampling, Gtr) {
  expect_sampler<Gtr>({0.01, 1.0}, 1);
  expect_sampler<Gtr>({0.3, 1.0});
  expect_sampler<Gtr>({0.3, 1.5});
  expect_sampler<Gtr>({0.1, 3.0});
  expect_sampler<Gtr>({0.5, 4.0}, 1);
}
TEST(NdfSampling, SgdExactInversion) {
  expect_sampler<Sgd>({0.01, 0.5}, 0, 40000);
  expect_sampler<Sgd>({0.2, 1.5}, 0, 40000);
  expect_sampler<Sgd>({0.05, 1.0}, 0, 40000);
  expect_sampler<Sgd>({1e-4, 0.8}, 0, 40000);
}
TEST(NdfSampling, ExponentialPower) {
  expect_sampler<ExponentialPower>({0.05, 0.5});
  expect_sampler<ExponentialPower>({0.3, 2.0}, 1);
}
TEST(NdfSampling, SchlickRational) {
  expect_sampler<SchlickRational>({0.01});
  expect_sampler<SchlickRational>({0.3});
  expect_sampler<SchlickRational>({1.0});
}
TEST(NdfSampling, SawickiRationalByTabulatedCdf) {
  expect_sampler<SawickiRational>({1.0}, 0, kSamples, 1.3);
  expect_sampler<SawickiRational>({100.0});
  expect_sampler<SawickiRational>({1e4});
}
TEST(NdfSampling, AbcFacet) {
  // pdf() is normalized (D cosθ / ∫ D cosθ dω) whatever A is.
  // Tails (1 − cosθ)^{−C} are free of B: with C ≤ 1 most mass is there, so perturb C.
  expect_sampler<AbcFacet>({3.0, 1.0, 1.0}, 1, kSamples, 1.3);
  expect_sampler<AbcFacet>({1.0, 1e4, 0.8}, 2);
  expect_sampler<AbcFacet>({1.0, 300.0, 2.5}, 1);
  expect_sampler<AbcFacet>({1.0, 1e6, 1.0 + 1e-9}, 2);
}

// Seed 003 Eq. 25–26 draws density ∝ S over solid angle: it passes against Eq. 23–24's pdf
// (both branches and C ≈ 1) and fails against the cosine-weighted density for a broad lobe.
TEST(NdfSampling, AbcFacetSeed003Sampler) {
  for (std::vector<double> p : {std::vector<double>{1.0, 2.0, 1.0}, {1.0, 500.0, 0.5}, {1.0, 50.0, 2.2}, {1.0, 50.0, 1.0 + 1e-12}}) {
    const AbcFacet<double> d(p.data());
    const auto r = chi2_theta_phi([&](const Vec2d& u) { return d.sample_paper(u); },
                                  [&](double c) { return d.pdf_paper(Vec3d(std::sqrt(1 - c * c), 0, c)); }, kSamples);
    EXPECT_GT(r.p_value, 0.01) << p[1] << " " << p[2];
  }
  const double p[3] = {1.0, 2.0, 1.0};
  const AbcFacet<double> d(p);
  const auto r = chi2_theta_phi([&](const Vec2d& u) { return d.sample_paper(u); },
                                [&](double c) { return d.pdf(Vec3d(std::sqrt(1 - c * c), 0, c)); }, kSamples);
  EXPECT_LT(r.p_value, 1e-6);
}

TEST(NdfSampling, TabulatedByTabulatedCdf) {
  const Tabulated<double> t({0.0, 0.05, 0.1, 0.2, 0.4, 0.8, 1.2}, {10.0, 8.0, 5.0, 2.0, 0.5, 0.1, 0.0});
  const auto r = chi2_theta_phi([&](const Vec2d& u) { return t.sample(u); },
                                [&](double c) { return t.pdf(Vec3d(std::sqrt(1 - c * c), 0, c)); }, kSamples);
  EXPECT_GT(r.p_value, 0.01);
  const Tabulated<double> other({0.0, 0.05, 0.1, 0.2, 0.4, 0.8, 1.2}, {10.0, 8.0, 5.0, 2.5, 0.5, 0.1, 0.0});
  const auto bad = chi2_theta_phi([&](const Vec2d& u) { return other.sample(u); },
                                  [&](double c) { return t.pdf(Vec3d(std::sqrt(1 - c * c), 0, c)); }, kSamples);
  EXPECT_LT(bad.p_value, 1e-4);
}

// DESIGN.md §6: seed 004 Eq. 23 prints tanθ = σ Q⁻¹(1/p, u)^{p/2}; the inversion of the slope
// CDF P(1/p, (x/σ²)^p) gives the exponent 1/(2p). The printed one fails unless p = 1.
TEST(NdfSampling, ExponentialPowerSeed004PrintedExponentFails) {
  for (double pp : {0.5, 2.0}) {
    const double params[2] = {0.2, pp};
    const ExponentialPower<double> d(params);
    auto printed = [&](const Vec2d& u) {
      const double y = boost::math::gamma_q_inv(1.0 / pp, 1.0 - u.x());
      const double th = std::atan(0.2 * std::pow(y, pp / 2));
      return Vec3d(std::sin(th) * std::cos(2 * kPi * u.y()), std::sin(th) * std::sin(2 * kPi * u.y()), std::cos(th));
    };
    auto pdf = [&](double c) { return d.pdf(Vec3d(std::sqrt(1 - c * c), 0, c)); };
    EXPECT_LT(chi2_theta_phi(printed, pdf, kSamples).p_value, 1e-6) << pp;
    EXPECT_GT(chi2_theta_phi([&](const Vec2d& u) { return d.sample(u); }, pdf, kSamples).p_value, 0.01) << pp;
  }
}

// Seed 000 §4.5's GGX proxy: E_ggx[w] = ∫ D_sgd cosθ dω = 1 and E_ggx[w cos²θ] = ∫ D_sgd cos³θ dω.
TEST(NdfSampling, SgdGgxProxyWeightsAreUnbiased) {
  for (std::vector<double> p : {std::vector<double>{0.05, 0.6}, {0.2, 1.3}}) {
    const Sgd<double> d(p.data());
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    const long n = 200000;
    double s1 = 0, s1sq = 0, s2 = 0, s2sq = 0;
    for (long i = 0; i < n; ++i) {
      double w = 0;
      const Vec3d m = d.sample_ggx_proxy(Vec2d(uni(rng), uni(rng)), &w);
      const double w2 = w * m.z() * m.z();
      s1 += w, s1sq += w * w, s2 += w2, s2sq += w2 * w2;
    }
    const double m1 = s1 / n, e1 = std::sqrt((s1sq / n - m1 * m1) / n);
    const double m2 = s2 / n, e2 = std::sqrt((s2sq / n - m2 * m2) / n);
    const double ref2 = test::cos_weighted_integral([&](double c) { return d.D(c) * c * c; });
    EXPECT_NEAR(m1, 1.0, 4 * e1) << p[0] << " " << p[1];
    EXPECT_NEAR(m2, ref2, 4 * e2) << p[0] << " " << p[1];
  }
}

}  // namespace
}  // namespace brdfkit
