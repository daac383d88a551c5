// Smith Λ from P22 (DESIGN.md §4): the one-integral form against the nested form of the spec,
// the direct integral and the table against the Beckmann and GGX closed forms, SGD table against
// the direct integral, Jets, thread-safe lazy build.
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>
#include <vector>

#include "brdfkit/ndf/beckmann.h"
#include "brdfkit/ndf/exponential_power.h"
#include "brdfkit/ndf/gaussian.h"
#include "brdfkit/ndf/ggx.h"
#include "brdfkit/ndf/gtr.h"
#include "brdfkit/ndf/sgd.h"
#include "brdfkit/shadowing/smith.h"
#include "support/sgd_for_tests.h"

namespace brdfkit {
namespace {

using boost::math::quadrature::gauss_kronrod;

double deg(double d) { return d * kPi / 180; }

// DESIGN.md §4 literally: P2(r) = ∫ P22(r² + q²) dq over ℝ, Λ = ∫_{1/t}^∞ (r t − 1) P2(r) dr,
// both by adaptive Gauss-Kronrod on infinite ranges (Boost maps them to finite ones).
template <class Ndf> double lambda_nested(const Ndf& ndf, double t) {
  auto p2 = [&](double r) {
    return 2 * gauss_kronrod<double, 31>::integrate([&](double q) { return ndf.P22(r * r + q * q); }, 0.0,
                                                   std::numeric_limits<double>::infinity(), 15, 1e-12);
  };
  return gauss_kronrod<double, 31>::integrate([&](double r) { return (r * t - 1) * p2(r); }, 1.0 / t,
                                             std::numeric_limits<double>::infinity(), 15, 1e-11);
}

TEST(Smith, OneIntegralFormEqualsNestedForm) {
  double max_rel = 0;
  for (double a : {0.1, 0.5}) {
    const Beckmann<double> b(&a);
    const Ggx<double> g(&a);
    for (double th : {30.0, 70.0, 85.0}) {
      const double t = std::tan(deg(th));
      const double nb = lambda_nested(b, t), ng = lambda_nested(g, t);
      if (nb > 1e-12) max_rel = std::max(max_rel, std::abs(smith_lambda_integral(b, t) / nb - 1));
      max_rel = std::max(max_rel, std::abs(smith_lambda_integral(g, t) / ng - 1));
    }
  }
  std::printf("one-integral vs nested Λ: max relative difference %.3g\n", max_rel);
  EXPECT_LT(max_rel, 1e-7);
}

// A distribution seen through its scalar P22 only, so that smith_lambda_integral takes the
// point-by-point path.
template <class Ndf> struct ScalarP22 {
  const Ndf& ndf;
  double P22(double x) const { return ndf.P22(x); }
};

// Worst relative difference between Λ with the vector integrand (shadowing/smith_integrand_block.h:
// vector pow or exp and log, exp and atan, each within 4 ulp of libm's) and the same quadrature
// point by point, over tanθ from 1e-3 to 1e3 for each parameter set.
template <class Ndf> double worst_vector_difference(const std::vector<std::vector<double>>& params) {
  static_assert(smith_detail::HasP22Block<Ndf>);
  double worst = 0;
  for (const auto& p : params) {
    const Ndf ndf(p.data());
    for (int k = 0; k <= 24; ++k) {
      const double t = std::pow(10.0, -3 + k * 0.25);
      const double scalar = smith_lambda_integral(ScalarP22<Ndf>{ndf}, t);
      const double vector = smith_lambda_integral(ndf, t);
      if (!(scalar > 1e-300)) {
        // Λ this small leaves G1 = 1 to the last bit; near the subnormals the relative difference
        // means nothing, so it is compared absolutely.
        EXPECT_NEAR(vector, scalar, 1e-300) << "tan " << t;
        continue;
      }
      worst = std::max(worst, std::abs(vector / scalar - 1));
    }
  }
  return worst;
}

// The lattice's factors (shadowing/smith_lattice_panels.h) are the integrand's own: an integral
// read from them equals, to the bit, the same quadrature with every factor computed afresh, and a
// window beyond the lattice (tanθ = 1e30: ln t = 69) still agrees with the point-by-point integral.
TEST(Smith, LatticeFactorsGiveTheFreshIntegralToTheBit) {
  for (const auto& p : std::vector<std::vector<double>>{{1e-3, 0.5}, {0.2, 2.0}, {0.9, 10.0}, {2.0, 1.0}}) {
    const Gtr<double> ndf(p.data());
    for (double t : {1e-3, 0.05, 0.3, 1.0, 7.0, 1e3}) {
      const double inv_t2 = 1 / (t * t), lt = std::log(t);
      const int i_lo = int(std::floor((-30 + std::min(0.0, lt)) / smith_detail::kPanelWidth));
      const int i_hi = int(std::ceil((45 + std::max(0.0, lt)) / smith_detail::kPanelWidth));
      auto fresh = [&](const std::vector<double>& w, std::vector<double>& out) {
        std::vector<double> x(w.size()), factor(w.size());
        smith_detail::integrand_factors(inv_t2, w.data(), w.size(), x.data(), factor.data());
        smith_detail::p22_products(ndf, x, factor, out);
      };
      const double want = smith_detail::integrate_log_panels_batched<double>(fresh, i_lo * smith_detail::kPanelWidth,
                                                                           i_hi * smith_detail::kPanelWidth);
      ASSERT_EQ(smith_detail::integrate_lattice_panels(ndf, inv_t2, i_lo, i_hi), want)
          << "alpha " << p[0] << " gamma " << p[1] << " tan " << t;
    }
    const double far = smith_lambda_integral(ndf, 1e30), point = smith_lambda_integral(ScalarP22<Gtr<double>>{ndf}, 1e30);
    EXPECT_NEAR(far / point, 1.0, 1e-12) << "alpha " << p[0] << " gamma " << p[1];
  }
}

// Over the Smith tables' boxes: GTR's α from 1e-3 to 2 and γ from 0.1 to 10, the Gaussian's m
// from 1e-3 to 1.5, SGD's α from 1e-4 to 2 and p from 0.05 to 1.9, the exponential power's σ from
// 1e-4 to 2 and p from 0.05 to 10.
TEST(Smith, VectorIntegrandAgreesWithThePointByPointIntegral) {
  std::vector<std::vector<double>> gtr, gaussian, sgd, exponential_power;
  for (double a : {1e-3, 0.01, 0.1, 0.5, 0.9, 0.999, 1.5, 2.0})
    for (double g : {0.1, 0.5, 1.0, 1.5, 2.0, 3.0, 6.0, 10.0}) gtr.push_back({a, g});
  for (double m : {1e-3, 0.01, 0.05, 0.2, 0.5, 1.0, 1.5}) gaussian.push_back({m});
  for (double a : {1e-4, 0.01, 0.1, 0.5, 2.0})
    for (double p : {0.05, 0.5, 1.0, 1.5, 1.9}) sgd.push_back({a, p});
  for (double s : {1e-4, 0.01, 0.1, 0.5, 2.0})
    for (double p : {0.05, 0.3, 1.0, 3.0, 10.0}) exponential_power.push_back({s, p});
  const double e_gtr = worst_vector_difference<Gtr<double>>(gtr);
  const double e_gaussian = worst_vector_difference<Gaussian<double>>(gaussian);
  const double e_sgd = worst_vector_difference<Sgd<double>>(sgd);
  const double e_power = worst_vector_difference<ExponentialPower<double>>(exponential_power);
  std::printf("Λ, vector integrand vs point by point: max relative difference GTR %.3g, Gaussian %.3g, SGD %.3g, "
              "exponential power %.3g\n",
              e_gtr, e_gaussian, e_sgd, e_power);
  EXPECT_LT(e_gtr, 1e-12);
  EXPECT_LT(e_gaussian, 1e-12);
  EXPECT_LT(e_sgd, 1e-12);
  EXPECT_LT(e_power, 1e-12);
}

// Max |ΔG1| over θ ∈ [0°, 89°] (1° steps) and α from 0.01 to 1, against the closed form.
template <template <class> class Ndf, class LambdaFn> double max_g1_error(LambdaFn&& numeric) {
  double worst = 0;
  for (double a : {0.01, 0.013, 0.02, 0.035, 0.05, 0.077, 0.1, 0.15, 0.2, 0.3, 0.5, 0.7, 1.0}) {
    const Ndf<double> ndf(&a);
    for (int d = 0; d <= 89; ++d) {
      const double t = std::tan(deg(d));
      const double g_ref = 1 / (1 + smith_lambda(ndf, t));
      const double g_num = 1 / (1 + numeric(ndf, t));
      worst = std::max(worst, std::abs(g_num - g_ref));
    }
  }
  return worst;
}

TEST(Smith, DirectIntegralMatchesClosedForms) {
  auto direct = [](const auto& ndf, double t) { return smith_lambda_integral(ndf, t); };
  const double eb = max_g1_error<Beckmann>(direct), eg = max_g1_error<Ggx>(direct);
  std::printf("direct integral, max |dG1|: Beckmann %.3g, GGX %.3g\n", eb, eg);
  EXPECT_LT(eb, 1e-9);
  EXPECT_LT(eg, 1e-9);
}

TEST(Smith, TableMatchesClosedForms) {
  auto table = [](const auto& ndf, double t) { return smith_lambda_numeric(ndf, t); };
  const double eb = max_g1_error<Beckmann>(table), eg = max_g1_error<Ggx>(table);
  std::printf("table, max |dG1|: Beckmann %.3g, GGX %.3g\n", eb, eg);
  EXPECT_LT(eb, 1e-5);
  EXPECT_LT(eg, 1e-5);
  // Off-grid α and θ, and grazing angles up to 89.99°.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0;
  for (int i = 0; i < 2000; ++i) {
    const double a = 1e-3 * std::pow(2000.0, u(rng));
    const double th = deg(89.99) * std::sqrt(u(rng));
    const double t = std::tan(th);
    const Beckmann<double> b(&a);
    const Ggx<double> g(&a);
    worst = std::max(worst, std::abs(1 / (1 + smith_lambda_numeric(b, t)) - 1 / (1 + b.Lambda(t))));
    worst = std::max(worst, std::abs(1 / (1 + smith_lambda_numeric(g, t)) - 1 / (1 + g.Lambda(t))));
  }
  std::printf("table, random (alpha in [1e-3, 2], theta < 89.99 deg): max |dG1| %.3g\n", worst);
  EXPECT_LT(worst, 1e-5);
}

// ndf/sgd.h's table against the direct integral of the independent P22 of sgd_for_tests.h.
TEST(Smith, SgdTableMatchesDirectIntegral) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0, worst_a = 0, worst_p = 0, worst_th = 0;
  for (int i = 0; i < 3000; ++i) {
    // The published fits' range (α 1.6e-5 … 0.85, p 0 … 1.78), then ndf/sgd.h's whole box.
    const bool published = i < 2000;
    const double a = published ? 1e-5 * std::pow(1e5, u(rng)) : 1e-6 * std::pow(2e6, u(rng));
    const double pv[2] = {a, published ? 1.8 * u(rng) : 1.95 * u(rng)};
    const double th = deg(89.9) * std::sqrt(u(rng));
    const double t = std::tan(th);
    const double tab = smith_lambda(Sgd<double>(pv), t);
    const double ref = smith_lambda_integral(test::TestSgd<double>(pv), t);
    const double e = std::abs(1 / (1 + tab) - 1 / (1 + ref));
    if (e > worst) {
      worst = e;
      worst_a = pv[0];
      worst_p = pv[1];
      worst_th = th;
    }
  }
  std::printf("SGD table (ndf/sgd.h) vs direct integral of an independent P22, alpha in [1e-6, 2], p in [0, 1.95]: "
              "max |dG1| %.3g at alpha %.3g p %.3g theta %.4f\n",
              worst, worst_a, worst_p, worst_th);
  EXPECT_LT(worst, 1e-5);
}

TEST(Smith, OutsideTableFallsBackToIntegral) {
  const double a = 3.0;  // above the Beckmann table's box [1e-3, 2]
  const Beckmann<double> b(&a);
  EXPECT_NEAR(smith_lambda_numeric(b, 0.7), b.Lambda(0.7), 1e-9);
}

TEST(Smith, JetDerivatives) {
  using J = ceres::Jet<double, 2>;
  // Table Λ for GGX: derivatives w.r.t. α and tanθ against the closed form's (via Jets).
  for (double a : {0.05, 0.3, 0.9})
    for (double th : {40.0, 75.0, 88.0}) {
      const double t = std::tan(deg(th));
      const J aj(a, 0);
      const Ggx<J> g(&aj);
      const J tab = smith_lambda_numeric(g, J(t, 1));
      const J ref = g.Lambda(J(t, 1));
      EXPECT_NEAR(tab.a, ref.a, 1e-5 * (1 + ref.a));
      EXPECT_NEAR(tab.v[0], ref.v[0], 2e-3 * (1 + std::abs(ref.v[0]))) << a << " " << th;
      EXPECT_NEAR(tab.v[1], ref.v[1], 2e-3 * (1 + std::abs(ref.v[1]))) << a << " " << th;
    }
  // Direct integral with Jets: exact derivatives of the quadrature, against the closed form.
  const J aj(0.2, 0);
  const Beckmann<J> b(&aj);
  const J dir = smith_lambda_integral(b, J(2.0, 1));
  const J ref = b.Lambda(J(2.0, 1));
  EXPECT_NEAR(dir.v[0], ref.v[0], 1e-8 * std::abs(ref.v[0]));
  EXPECT_NEAR(dir.v[1], ref.v[1], 1e-8 * std::abs(ref.v[1]));
  // SGD: table derivative w.r.t. p against a central difference of the direct integral.
  const double v[2] = {0.05, 0.6}, t = std::tan(deg(80));
  const J vj[2] = {J(v[0], 0), J(v[1], 1)};
  const J s = smith_lambda(Sgd<J>(vj), J(t));
  const double h = 1e-4;
  const double vp[2] = {v[0], v[1] + h}, vm[2] = {v[0], v[1] - h};
  const double dp = (smith_lambda_integral(test::TestSgd<double>(vp), t) - smith_lambda_integral(test::TestSgd<double>(vm), t)) / (2 * h);
  EXPECT_NEAR(s.v[1], dp, 2e-3 * std::abs(dp));
}

TEST(Smith, GFormsAndSymmetry) {
  const double a = 0.4;
  const Ggx<double> g(&a);
  const double ci = std::cos(deg(60)), co = std::cos(deg(30));
  const double li = g.Lambda(std::tan(deg(60))), lo = g.Lambda(std::tan(deg(30)));
  EXPECT_NEAR(smith_g_uncorrelated(g, ci, co), 1 / ((1 + li) * (1 + lo)), 1e-15);
  EXPECT_NEAR(smith_g_correlated(g, ci, co), 1 / (1 + li + lo), 1e-15);
  EXPECT_DOUBLE_EQ(smith_g_correlated(g, ci, co), smith_g_correlated(g, co, ci));
  EXPECT_GE(smith_g_correlated(g, ci, co), smith_g_uncorrelated(g, ci, co));
  EXPECT_EQ(smith_g1(g, 1.0), 1.0);
  EXPECT_EQ(smith_g1(g, 0.0), 0.0);
  EXPECT_EQ(smith_g_correlated(g, -0.1, co), 0.0);
}

// A family used only here, so its table is built by the threads below (concurrent first use).
template <class T> struct ThreadTestGgx {
  T alpha;
  explicit ThreadTestGgx(const T* p) : alpha(p[0]) {}
  T P22(const T& x) const { return Ggx<T>(&alpha).P22(x); }
};
}  // namespace
template <> struct SmithShape<ThreadTestGgx> {
  static constexpr int kDims = 1;
  static std::vector<SmithAxis> axes() { return {{0.05, 1.0, 6, true}}; }
  template <class T> static std::array<T, 1> values(const ThreadTestGgx<T>& d) { return {d.alpha}; }
};
namespace {

TEST(Smith, ConcurrentLazyBuild) {
  std::vector<double> out(8);
  std::vector<std::thread> threads;
  for (int i = 0; i < 8; ++i)
    threads.emplace_back([&out, i] {
      const double a = 0.3;
      out[size_t(i)] = smith_lambda_numeric(ThreadTestGgx<double>(&a), 1.5 + 0 * i);
    });
  for (auto& th : threads) th.join();
  const double a = 0.3;
  for (double v : out) {
    EXPECT_EQ(v, out[0]);
    EXPECT_NEAR(v, Ggx<double>(&a).Lambda(1.5), 1e-6);
  }
}

}  // namespace
}  // namespace brdfkit
