// D, P22 and unit in ceres::Jet equal the double evaluation, and their parameter derivatives
// match central finite differences to 1e-6 relative (DESIGN.md §1: one template for doubles and
// Jets). Covers the derivatives that are not automatic: SGD's Γ(1−p, α), the Gaussian's numeric
// normalization, Γ(1/p) of the exponential power, GTR across γ = 1, ABC's closed-form integral.
#include <gtest/gtest.h>

#include <ceres/jet.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "support/all_ndfs.h"
#include "support/ndf_test_util.h"

namespace brdfkit {
namespace {

using test::expect_jets;
using J = ceres::Jet<double, 3>;

TEST(NdfJets, Beckmann) { expect_jets<Beckmann>({0.2}); }
TEST(NdfJets, Ggx) { expect_jets<Ggx>({0.2}); }
TEST(NdfJets, BlinnPhong) { expect_jets<BlinnPhong>({30.0}); }
TEST(NdfJets, GaussianNumericNormalization) {
  expect_jets<Gaussian>({0.2});
  expect_jets<Gaussian>({1.2});
}
TEST(NdfJets, Exponential) { expect_jets<Exponential>({0.2}); }
TEST(NdfJets, GtrAcrossGammaOne) {
  expect_jets<Gtr>({0.2, 1.0});
  expect_jets<Gtr>({0.2, 1.0 + 2e-4});
  expect_jets<Gtr>({0.2, 2.5});
  expect_jets<Gtr>({0.6, 0.5});
}
TEST(NdfJets, SgdIncompleteGammaDerivatives) {
  expect_jets<Sgd>({0.05, 0.6});
  expect_jets<Sgd>({0.2, 1.5});   // 1 − p < 0: recurrence branch
  expect_jets<Sgd>({0.1, 1.0});   // 1 − p = 0: E1
  expect_jets<Sgd>({0.01, 0.2});
}
TEST(NdfJets, ExponentialPower) {
  expect_jets<ExponentialPower>({0.2, 0.7});
  expect_jets<ExponentialPower>({0.1, 2.5});
}
TEST(NdfJets, SchlickRational) { expect_jets<SchlickRational>({0.4}); }
TEST(NdfJets, SawickiRational) { expect_jets<SawickiRational>({50.0}); }
TEST(NdfJets, AbcFacet) {
  expect_jets<AbcFacet>({2.0, 100.0, 1.5});
  expect_jets<AbcFacet>({2.0, 100.0, 1.0});
  std::vector<J> pj = {J(2.0, 0), J(100.0, 1), J(1.7, 2)};
  const AbcFacet<J> dj(pj.data());
  const J n = dj.normalization();
  for (int i = 0; i < 3; ++i) {
    double p[3] = {2.0, 100.0, 1.7}, q[3] = {2.0, 100.0, 1.7};
    const double h = 1e-5 * p[i];
    p[i] += h, q[i] -= h;
    const double fd = (AbcFacet<double>(p).normalization() - AbcFacet<double>(q).normalization()) / (2 * h);
    EXPECT_NEAR(n.v[i], fd, 1e-6 * std::abs(fd)) << i;
  }
}
TEST(NdfJets, TabulatedValues) {
  const std::vector<double> th = {0.0, 0.1, 0.3, 0.8};
  std::vector<J> v = {J(4.0, 0), J(3.0, 1), J(1.0, 2), J(0.2)};
  const Tabulated<J> tj(th, v);
  for (double c : {0.999, 0.98, 0.9}) {
    const J Dj = tj.D(J(c));
    for (int i = 0; i < 3; ++i) {
      std::vector<double> a = {4.0, 3.0, 1.0, 0.2}, b = a;
      a[i] += 1e-5, b[i] -= 1e-5;
      const double fd = (Tabulated<double>(th, a).D(c) - Tabulated<double>(th, b).D(c)) / 2e-5;
      EXPECT_NEAR(Dj.v[i], fd, 1e-6 * std::max(1e-3, std::abs(fd))) << c << " " << i;
    }
  }
}

}  // namespace
}  // namespace brdfkit
