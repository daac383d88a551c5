// Fresnel terms (DESIGN.md §5): limits, an independent Snell/Fresnel computation, published values.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "brdfkit/core/vec.h"
#include "brdfkit/fresnel/bagher_fresnel.h"
#include "brdfkit/fresnel/conductor.h"
#include "brdfkit/fresnel/dielectric.h"
#include "brdfkit/fresnel/no_fresnel.h"
#include "brdfkit/fresnel/schlick.h"

namespace brdfkit {
namespace {

// Unpolarized reflectance from the s and p amplitude coefficients with complex Snell's law
// (Born & Wolf §1.5.2, §14.2): n1 = 1, n2 = η + ik, cosθt = sqrt(1 − sin²θ / n2²).
double fresnel_sp(std::complex<double> n2, double cos_i) {
  const double sin2 = 1.0 - cos_i * cos_i;
  const std::complex<double> cos_t = std::sqrt(1.0 - sin2 / (n2 * n2));
  const std::complex<double> rs = (cos_i - n2 * cos_t) / (cos_i + n2 * cos_t);
  const std::complex<double> rp = (n2 * cos_i - cos_t) / (n2 * cos_i + cos_t);
  return 0.5 * (std::norm(rs) + std::norm(rp));
}

TEST(Fresnel, SchlickLimits) {
  for (double f0 : {0.0, 0.04, 0.5, 0.95}) {
    SchlickFresnel<double> f(&f0);
    EXPECT_DOUBLE_EQ(f.eval(1.0), f0);
    EXPECT_DOUBLE_EQ(f.eval(0.0), 1.0);
    EXPECT_NEAR(f.eval(0.5), f0 + (1 - f0) / 32.0, 1e-15);
  }
}

TEST(Fresnel, BagherAsPublished) {
  // white-paint-like case F1 > F0: negative near θd = 0 (DESIGN.md §5), 1 at grazing.
  const double p[2] = {0.1, 0.17};
  BagherFresnel<double> f(p);
  EXPECT_NEAR(f.eval(1.0), 0.1 - 0.17, 1e-15);
  EXPECT_DOUBLE_EQ(f.eval(0.0), 1.0);
  EXPECT_NEAR(f.eval(0.3), 0.1 + 0.9 * std::pow(0.7, 5) - 0.17 * 0.3, 1e-15);
}

TEST(Fresnel, DielectricNormalAndGrazing) {
  for (double eta : {1.0, 1.33, 1.5, 2.4, 9.8}) {
    DielectricFresnel<double> f(&eta);
    const double r0 = (eta - 1) / (eta + 1);
    EXPECT_NEAR(f.eval(1.0), r0 * r0, 1e-15) << eta;
    EXPECT_DOUBLE_EQ(f.eval(0.0), 1.0);
    // η = 1 is no interface at all (F = 0 except exactly at c = 0); otherwise F → 1 at grazing.
    if (eta > 1) {
      EXPECT_GT(f.eval(1e-4), 0.99) << eta;
    }
  }
}

TEST(Fresnel, DielectricMatchesSnellSP) {
  double max_err = 0;
  for (double eta : {1.05, 1.33, 1.5, 2.0, 4.0, 99.99}) {
    DielectricFresnel<double> f(&eta);
    for (double deg = 0; deg < 90.0; deg += 2.5) {
      const double c = std::cos(deg * kPi / 180);
      max_err = std::max(max_err, std::abs(f.eval(c) - fresnel_sp({eta, 0.0}, c)));
    }
  }
  std::printf("dielectric vs s/p Snell: max |diff| = %.3g\n", max_err);
  EXPECT_LT(max_err, 1e-12);
}

TEST(Fresnel, ConductorWithoutExtinctionIsDielectric) {
  for (double eta : {1.1, 1.5, 3.0}) {
    const double pc[2] = {eta, 0.0};
    ConductorFresnel<double> fc(pc);
    DielectricFresnel<double> fd(&eta);
    for (double deg = 0; deg < 90.0; deg += 5)
      EXPECT_NEAR(fc.eval(std::cos(deg * kPi / 180)), fd.eval(std::cos(deg * kPi / 180)), 1e-13) << eta << " " << deg;
  }
}

TEST(Fresnel, ConductorMatchesComplexSnell) {
  // Gold-, copper- and aluminium-like indices; complex-amplitude Fresnel equations as reference.
  double max_err = 0;
  for (auto nk : {std::complex<double>(0.2, 3.0), std::complex<double>(0.23883, 3.415658),
                  std::complex<double>(1.26232, 7.1855), std::complex<double>(2.5, 0.5)}) {
    const double p[2] = {nk.real(), nk.imag()};
    ConductorFresnel<double> f(p);
    for (double deg = 0; deg < 90.0; deg += 2.5) {
      const double c = std::cos(deg * kPi / 180);
      max_err = std::max(max_err, std::abs(f.eval(c) - fresnel_sp(nk, c)));
    }
  }
  std::printf("conductor vs complex Snell s/p: max |diff| = %.3g\n", max_err);
  EXPECT_LT(max_err, 1e-12);
}

TEST(Fresnel, AluminiumReference) {
  // Aluminium at λ = 0.6 µm: n = 1.26232, k = 7.1855, normal reflectance 0.91103
  // (RefractiveIndex.INFO database and its forum's worked example, "Reflection coefficient").
  const double p[2] = {1.26232, 7.1855};
  ConductorFresnel<double> f(p);
  EXPECT_NEAR(f.eval(1.0), 0.91103, 5e-6);
  EXPECT_DOUBLE_EQ(f.eval(0.0), 1.0);
}

TEST(Fresnel, NoFresnelIsOne) {
  NoFresnel<double> f;
  EXPECT_EQ(NoFresnel<double>::params().size(), 0u);
  EXPECT_EQ(f.eval(0.3), 1.0);
}

TEST(Fresnel, JetsMatchDoublesAndFiniteDifferences) {
  using J = ceres::Jet<double, 2>;
  const double c = 0.37, h = 1e-6;
  // Dielectric: ∂F/∂η and ∂F/∂c.
  {
    const double eta = 1.7;
    J pj[1] = {J(eta, 0)};
    const J fj = DielectricFresnel<J>(pj).eval(J(c, 1));
    const double e_p = eta + h, e_m = eta - h;
    const double d_eta = (DielectricFresnel<double>(&e_p).eval(c) - DielectricFresnel<double>(&e_m).eval(c)) / (2 * h);
    const double d_c = (DielectricFresnel<double>(&eta).eval(c + h) - DielectricFresnel<double>(&eta).eval(c - h)) / (2 * h);
    EXPECT_DOUBLE_EQ(fj.a, DielectricFresnel<double>(&eta).eval(c));
    EXPECT_NEAR(fj.v[0], d_eta, 1e-7 * std::max(1.0, std::abs(d_eta)));
    EXPECT_NEAR(fj.v[1], d_c, 1e-7 * std::max(1.0, std::abs(d_c)));
  }
  // Conductor: ∂F/∂η, ∂F/∂k.
  {
    const double p[2] = {0.3, 3.1};
    J pj[2] = {J(p[0], 0), J(p[1], 1)};
    const J fj = ConductorFresnel<J>(pj).eval(J(c));
    EXPECT_DOUBLE_EQ(fj.a, ConductorFresnel<double>(p).eval(c));
    for (int i = 0; i < 2; ++i) {
      double pp[2] = {p[0], p[1]}, pm[2] = {p[0], p[1]};
      pp[i] += h;
      pm[i] -= h;
      const double fd = (ConductorFresnel<double>(pp).eval(c) - ConductorFresnel<double>(pm).eval(c)) / (2 * h);
      EXPECT_NEAR(fj.v[i], fd, 1e-7 * std::max(1.0, std::abs(fd)));
    }
  }
}

TEST(Fresnel, ParamTables) {
  EXPECT_EQ(SchlickFresnel<double>::params().at(0).scope, Scope::PerChannel);
  EXPECT_EQ(DielectricFresnel<double>::params().at(0).name, "eta");
  EXPECT_EQ(ConductorFresnel<double>::params().size(), 2u);
  EXPECT_EQ(BagherFresnel<double>::params().size(), 2u);
}

}  // namespace
}  // namespace brdfkit
