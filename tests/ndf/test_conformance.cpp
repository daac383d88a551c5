// What every distribution of ndf/distributions.h must satisfy, run on each of them from that list
// alone (a new distribution gets these tests with no edit here): ∫ D cosθ dω = 1, P22 and D agree
// (seed 000 Eq. 2–3), sampling draws D cosθ (χ²), Jets equal doubles and central differences, the
// Smith Λ table (where the distribution has one) equals the direct integral, and the catalogue
// holds its Cook-Torrance model. Parameters: the table's defaults and each shape parameter moved
// by a factor 0.6 and 1.6 (or ±10 % of its box), so every point is an ordinary lobe of the family.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "brdfkit/models/model.h"
#include "brdfkit/ndf/distributions.h"
#include "brdfkit/shadowing/smith.h"
#include "support/ndf_test_util.h"

namespace brdfkit {
namespace {

template <template <class> class D> struct Tag {
  template <class T> using type = D<T>;
  static std::string name() { return std::string(D<double>::kName); }
};
template <template <class> class... Ds> using TagTypes = testing::Types<Tag<Ds>...>;
using AllDistributions = Distributions::apply<TagTypes>;

struct TagName {
  template <class T> static std::string GetName(int) { return T::name(); }
};

template <class T> class DistributionConformance : public testing::Test {};
TYPED_TEST_SUITE(DistributionConformance, AllDistributions, TagName);

// The defaults, then each parameter moved alone (inside its bounds).
std::vector<std::vector<double>> parameter_sets(const ParamTable& table) {
  std::vector<double> def;
  for (const ParamSpec& s : table) def.push_back(s.def);
  std::vector<std::vector<double>> sets = {def};
  for (size_t k = 0; k < table.size(); ++k)
    for (double f : {0.6, 1.6}) {
      std::vector<double> p = def;
      const ParamSpec& s = table[k];
      p[k] = def[k] > 0 ? def[k] * f : def[k] + (f < 1 ? -0.1 : 0.1) * (s.upper - s.lower);
      p[k] = std::clamp(p[k], s.lower, s.upper);
      if (p[k] != def[k]) sets.push_back(p);
    }
  return sets;
}

template <class Tg> auto sets() { return parameter_sets(Tg::template type<double>::params()); }

TYPED_TEST(DistributionConformance, NormalizedAndP22AgreesWithD) {
  using N = typename TypeParam::template type<double>;
  for (const auto& p : sets<TypeParam>()) {
    const N d(p.data());
    const double integral = test::cos_weighted_integral([&](double c) { return d.D(c); });
    EXPECT_NEAR(integral, 1.0, 2e-4) << test::describe_params(p);
    for (double c : {0.2, 0.6, 0.9, 0.999}) {
      const double x = (1 - c * c) / (c * c);
      EXPECT_NEAR(d.P22(x) / (c * c * c * c), d.D(c), 1e-10 * d.D(c)) << test::describe_params(p) << " c " << c;
      EXPECT_NEAR(d.unit(c), d.D(c) / d.D(1.0), 1e-10 * d.unit(c) + 1e-300) << test::describe_params(p);
    }
    EXPECT_EQ(d.D(0.0), 0.0);
    EXPECT_EQ(d.D(-0.5), 0.0);
  }
}

TYPED_TEST(DistributionConformance, SamplingDrawsDCosTheta) {
  using N = typename TypeParam::template type<double>;
  for (const auto& p : sets<TypeParam>()) {
    const N d(p.data());
    const test::Chi2Outcome r = test::chi2_theta_phi([&](const Vec2d& u) { return d.sample(u); },
                                                     [&](double c) { return d.D(c) * c; }, 200000);
    // 1e-4: a Šidák bound for ~50 (distribution, parameter) cases at a family-wise 0.5 %.
    EXPECT_GT(r.p_value, 1e-4) << test::describe_params(p) << " chi2 " << r.statistic << " dof " << r.dof;
    for (double c : {0.3, 0.8, 0.99}) {
      const Vec3d m(std::sqrt(1 - c * c), 0.0, c);
      EXPECT_NEAR(d.pdf(m), d.D(c) * c, 1e-12 * d.D(c));
    }
  }
}

TYPED_TEST(DistributionConformance, JetsEqualDoublesAndCentralDifferences) {
  for (const auto& p : sets<TypeParam>()) test::expect_jets<TypeParam::template type>(p);
}

TYPED_TEST(DistributionConformance, SmithTableEqualsTheDirectIntegral) {
  using N = typename TypeParam::template type<double>;
  if constexpr (SmithShape<TypeParam::template type>::kDims == 0) {
    GTEST_SKIP() << TypeParam::name() << " has a closed-form Smith Λ (or none tabulated)";
  } else {
    for (const auto& p : sets<TypeParam>()) {
      const N d(p.data());
      for (double t : {0.1, 0.4, 1.0, 2.5, 8.0}) {
        const double table = 1 / (1 + smith_lambda(d, t)), direct = 1 / (1 + smith_lambda_integral(d, t));
        EXPECT_NEAR(table, direct, 1e-4) << test::describe_params(p) << " tan " << t;
      }
    }
  }
}

TYPED_TEST(DistributionConformance, CatalogueHasItsCookTorranceModel) {
  const std::string name = "cook-torrance-" + TypeParam::name();
  const Model& m = model_by_name(name);
  EXPECT_EQ(m.name(), name);
  EXPECT_NE(std::string(m.description()).find(std::string(TypeParam::template type<double>::kTitle)), std::string::npos);
}

}  // namespace
}  // namespace brdfkit
