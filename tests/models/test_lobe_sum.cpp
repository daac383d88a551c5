// Multi-lobe sums (models/lobe_sum.h): the sum equals the sum of its components
// evaluated separately, it has one diffuse term, it is reciprocal, and its mixture sampling
// passes the χ² test (and fails it with the pdf doubled).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "brdfkit/analysis/chi2_test.h"
#include "brdfkit/analysis/model_checks.h"
#include "brdfkit/core/error.h"
#include "brdfkit/models/lobe_sum.h"
#include "brdfkit/models/model.h"

namespace brdfkit {
namespace {

// Seed 002 §4.2's two Cook-Torrance lobes (Ngan's Beckmann + Schlick + V-groove), a diffuse
// term with two lobes of different kinds, and two Lafortune models (seed 002 §4.2) summed.
const char* const kSums[] = {"cook-torrance+cook-torrance", "lambert+ward+blinn-phong", "lafortune+lafortune"};

// Random values: colours uniform in [lower, min(upper, 1)], shapes between the defaults moved
// 35 % towards each bound (geometrically, by at most a factor 3, as tests/models/param_sets.h
// does), so every lobe stays in the range a quadrature resolves.
double moved(const ParamSpec& s, double target) {
  if (s.def > 0 && target > 0) return s.def * std::clamp(std::pow(target / s.def, 0.35), 1.0 / 3.0, 3.0);
  return s.def + (target - s.def) * 0.35;
}
ParamValues random_values(const ParamTable& t, std::mt19937_64& rng) {
  ParamValues v = ParamValues::defaults(t);
  std::uniform_real_distribution<double> u(0, 1);
  for (size_t i = 0; i < t.size(); ++i) {
    const ParamSpec& s = t[i];
    const double lo = s.linear ? s.lower : moved(s, s.lower), hi = s.linear ? std::min(s.upper, 1.0) : moved(s, s.upper);
    for (int c = 0; c < 3; ++c)
      v.values[size_t(c)][i] = s.scope == Scope::Shared && c > 0 ? v.values[0][i] : lo + (hi - lo) * u(rng);
  }
  return v;
}

// Each component's values taken from the sum's by name: `kd` → the component's kd (0 after the
// component that supplies it), `<j>.<name>` → its `<name>`.
ParamValues component_values(const LobeSum& sum, size_t j, const ParamValues& v, bool& took_kd) {
  const Model& m = sum.component(j);
  ParamValues out = ParamValues::defaults(m.params());
  for (size_t i = 0; i < m.params().size(); ++i) {
    const std::string& n = m.params()[i].name;
    const int k = n == "kd" ? (took_kd ? -1 : find_param(sum.params(), "kd"))
                            : find_param(sum.params(), std::to_string(j + 1) + "." + n);
    if (n == "kd" && !took_kd) took_kd = true;
    for (int c = 0; c < 3; ++c) out.values[size_t(c)][i] = k >= 0 ? v.values[size_t(c)][size_t(k)] : 0.0;
  }
  return out;
}

TEST(LobeSum, TableHasOneDiffuseTermAndPrefixedNames) {
  const Model& m = model_by_name("cook-torrance+cook-torrance");
  const ParamTable& t = m.params();
  std::vector<std::string> names;
  for (const auto& s : t) names.push_back(s.name);
  EXPECT_EQ(names, (std::vector<std::string>{"kd", "1.ks", "1.alpha", "1.F0", "2.ks", "2.alpha", "2.F0"}));
  const Model& one = model_by_name("cook-torrance");
  for (const char* n : {"ks", "alpha", "F0"}) {
    const ParamSpec& a = one.params()[size_t(find_param(one.params(), n))];
    const ParamSpec& b = t[size_t(find_param(t, std::string("2.") + n))];
    EXPECT_EQ(a.lower, b.lower) << n;
    EXPECT_EQ(a.upper, b.upper) << n;
    EXPECT_EQ(a.linear, b.linear) << n;
    EXPECT_EQ(a.scope, b.scope) << n;
  }
  // The repeated lobe starts sharper, so a fit from the defaults is not at a symmetric point.
  const double a1 = t[size_t(find_param(t, "1.alpha"))].def, a2 = t[size_t(find_param(t, "2.alpha"))].def;
  EXPECT_EQ(a1, one.params()[size_t(find_param(one.params(), "alpha"))].def);
  EXPECT_LT(a2, a1);
  EXPECT_GE(a2, a1 / 3 - 1e-12);
  EXPECT_TRUE(m.reciprocal());
  // The same object each time: a Brdf may hold a pointer to it.
  EXPECT_EQ(&m, &model_by_name("cook-torrance+cook-torrance"));

  const ParamTable& t3 = model_by_name("lambert+ward+blinn-phong").params();
  names.clear();
  for (const auto& s : t3) names.push_back(s.name);
  EXPECT_EQ(names, (std::vector<std::string>{"kd", "2.ks", "2.alpha", "3.ks", "3.N"}));
}

TEST(LobeSum, BadNamesAreInputErrors) {
  EXPECT_THROW(model_by_name("cook-torrance+nope"), InputError);
  EXPECT_THROW(model_by_name("cook-torrance+"), InputError);
  EXPECT_THROW(model_by_name("+ward"), InputError);
  EXPECT_THROW(model_by_name("ward+lambert"), InputError);  // the second lambert would have no parameter
  try {
    model_by_name("ward+lamber");
    FAIL();
  } catch (const InputError& e) {
    // The component named as given ("lamber" alone would match the list of known names' "lambert").
    EXPECT_NE(std::string(e.what()).find("component: model 'lamber': unknown"), std::string::npos) << e.what();
  }
}

TEST(LobeSum, EqualsTheSumOfItsComponents) {
  std::mt19937_64 rng(44);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0;
  for (const char* name : kSums) {
    const auto& sum = dynamic_cast<const LobeSum&>(model_by_name(name));
    for (int set = 0; set < 5; ++set) {
      const ParamValues v = random_values(sum.params(), rng);
      std::vector<ParamValues> parts;
      bool took_kd = false;
      for (size_t j = 0; j < sum.component_count(); ++j) parts.push_back(component_values(sum, j, v, took_kd));
      for (int k = 0; k < 50; ++k) {
        const Vec3d wi = spherical_direction(std::acos(u(rng)), 2 * kPi * u(rng));
        const Vec3d wo = spherical_direction(std::acos(u(rng)), 2 * kPi * u(rng));
        for (int c = 0; c < 3; ++c) {
          double want = 0;
          for (size_t j = 0; j < sum.component_count(); ++j)
            want += sum.component(j).eval(parts[j].channel(c), c, wi, wo);
          const double got = sum.eval(v.channel(c), c, wi, wo);
          ASSERT_TRUE(std::isfinite(got)) << name;
          const double rel = std::abs(got - want) / std::max(std::abs(want), 1e-300);
          worst = std::max(worst, rel);
          EXPECT_LE(rel, 1e-14) << name << " set " << set;
        }
      }
    }
  }
  std::printf("sum vs separately evaluated components: worst relative difference %.3g\n", worst);
}

TEST(LobeSum, Reciprocity) {
  std::mt19937_64 rng(45);
  for (const char* name : kSums) {
    const Model& m = model_by_name(name);
    for (int set = 0; set < 3; ++set) {
      const ParamValues v = random_values(m.params(), rng);
      const ReciprocityCheck r = reciprocity_check(m, v.channel(0), 0, 500, 99 + unsigned(set));
      EXPECT_LE(r.max_relative_error, 1e-10) << name;
      EXPECT_GT(r.pairs, 0);
      std::printf("%s set %d: reciprocity %.3g over %d pairs\n", name, set, r.max_relative_error, r.pairs);
    }
  }
}

// Two mixtures at normal, oblique and grazing viewing: a broad + sharp Cook-Torrance pair, and
// Lambert + Ward + Blinn-Phong.
struct MixtureCase {
  const char* model;
  std::vector<std::string> params;
};
const MixtureCase kMixtures[] = {
    {"cook-torrance+cook-torrance", {"kd=0.2", "1.ks=0.6", "1.alpha=0.4", "2.ks=0.3", "2.alpha=0.08", "1.F0=0.1"}},
    {"lambert+ward+blinn-phong", {"kd=0.3", "2.ks=0.2", "2.alpha=0.15", "3.ks=0.4", "3.N=200"}},
};
const double kThetaODeg[] = {0, 45, 80};

ParamValues values_of(const Model& m, const std::vector<std::string>& args) {
  ParamValues v = ParamValues::defaults(m.params());
  for (const auto& a : args) {
    const size_t eq = a.find('=');
    v.set(m.params(), a.substr(0, eq), std::stod(a.substr(eq + 1)));
  }
  return v;
}

TEST(LobeSum, MixtureSamplingPassesChi2) {
  const int family = int(std::size(kMixtures) * std::size(kThetaODeg));
  for (const auto& mc : kMixtures) {
    const auto& m = dynamic_cast<const LobeSum&>(model_by_name(mc.model));
    const ParamValues v = values_of(m, mc.params);
    for (double t : kThetaODeg) {
      const Vec3d wo = spherical_direction(t * kPi / 180, 0.3);
      Chi2Options o;
      o.samples = 100000;
      o.seed = 7 + unsigned(t);
      o.test_count = family;
      const Chi2Result r = chi2_test(m, v.channel(1), 1, wo, o);
      const auto prob = m.selection_probabilities(v.channel(1), 1, wo);
      std::printf("%s theta_o %2.0f: chi2 %.1f dof %d p %.4f, int pdf %.6f, rejected %.6f, P = %.3f %.3f %.3f\n",
                  mc.model, t, r.statistic, r.dof, r.p_value, r.pdf_integral, r.rejected_fraction, prob[0], prob[1],
                  m.component_count() > 2 ? prob[2] : 0.0);
      EXPECT_TRUE(r.passed) << mc.model << " theta_o " << t << ": " << r.message;
      EXPECT_LE(r.pdf_integral, 1 + 1e-4);
      double total = 0;
      for (size_t j = 0; j < m.component_count(); ++j) {
        EXPECT_GE(prob[j], 0.02 / double(m.component_count()) - 1e-15);
        total += prob[j];
      }
      EXPECT_NEAR(total, 1.0, 1e-12);
    }
  }
}

TEST(LobeSum, Chi2FailsWithPdfTimesTwo) {
  for (const auto& mc : kMixtures) {
    const Model& m = model_by_name(mc.model);
    const ParamValues v = values_of(m, mc.params);
    for (double t : kThetaODeg) {
      const Vec3d wo = spherical_direction(t * kPi / 180, 0.3);
      Chi2Options o;
      o.samples = 20000;
      const auto r = chi2_test([&](const Vec2d& u, double ul) { return m.sample(v.channel(0), 0, wo, u, ul); },
                               [&](const Vec3d& wi) { return 2 * m.pdf(v.channel(0), 0, wo, wi); }, o);
      EXPECT_FALSE(r.passed) << mc.model << " theta_o " << t;
      EXPECT_NEAR(r.pdf_integral, 2 * (1 - r.rejected_fraction), 0.02) << mc.model;
    }
  }
}

// The selection follows the lobes' albedos: a lobe with ks = 0 gets only the uniform share.
TEST(LobeSum, SelectionFollowsAlbedoEstimates) {
  const auto& m = dynamic_cast<const LobeSum&>(model_by_name("cook-torrance+cook-torrance"));
  ParamValues v = values_of(m, {"kd=0.2", "1.ks=0.5", "2.ks=0"});
  const auto prob = m.selection_probabilities(v.channel(0), 0, spherical_direction(0.5, 0.0));
  EXPECT_NEAR(prob[1], 0.01, 1e-12);
  EXPECT_NEAR(prob[0], 0.99, 1e-12);
}

}  // namespace
}  // namespace brdfkit
