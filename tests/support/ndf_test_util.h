#pragma once
// Helpers of the ndf tests: a quadrature of ∫ D cosθ dω independent of the distributions'
// own normalization code, and a χ² goodness-of-fit test of a θ sampler against a density.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "brdfkit/core/vec.h"

namespace brdfkit::test {

// "params 0.2 1.5" for failure messages (ostringstream: GCC 12's -Wrestrict misfires on
// string concatenation at -O3).
inline std::string describe_params(const std::vector<double>& p) {
  std::ostringstream os;
  os << "params";
  for (double v : p) os << ' ' << v;
  return os.str();
}

// θ = (π/2) t⁴ crowds quadrature nodes and χ² bins near θ = 0, where lobes as narrow as
// 0.005 rad live: such a lobe spans t ∈ [0, 0.2].
inline double theta_of_t(double t) { return kPi / 2 * t * t * t * t; }
inline double dtheta_dt(double t) { return kPi / 2 * 4 * t * t * t; }

// ∫_{θ(t0)}^{θ(t1)} 2π f(cosθ) sinθ dθ, adaptive Gauss-Kronrod in t, on `pieces` sub-intervals.
inline double integrate_over_theta(const std::function<double(double)>& f_of_cos, double t0, double t1, int pieces = 16) {
  using boost::math::quadrature::gauss_kronrod;
  double sum = 0.0;
  for (int k = 0; k < pieces; ++k) {
    const double a = t0 + (t1 - t0) * k / pieces, b = t0 + (t1 - t0) * (k + 1) / pieces;
    sum += gauss_kronrod<double, 31>::integrate(
        [&](double t) {
          const double th = theta_of_t(t);
          return 2 * kPi * f_of_cos(std::cos(th)) * std::sin(th) * dtheta_dt(t);
        },
        a, b, 10, 1e-10);
  }
  return sum;
}

// ∫ D(ωm) cosθm dωm over the hemisphere.
inline double cos_weighted_integral(const std::function<double(double)>& D) {
  return integrate_over_theta([&](double c) { return D(c) * c; }, 0.0, 1.0, 16);
}

struct Chi2Outcome {
  double p_value = 0;
  double statistic = 0;
  int dof = 0;
};

// Pearson χ² of `samples` draws of `sample(u)` against `pdf` (density over solid angle of an
// isotropic distribution): bins in θ (40, on the t⁴ map) × φ (4), expected counts by quadrature
// of the pdf per bin, consecutive bins pooled until each expects ≥ 5, plus one bin for the mass
// the pdf misses (a pdf that does not integrate to 1 fails). p from Boost's χ² distribution.
inline Chi2Outcome chi2_theta_phi(const std::function<Vec3d(const Vec2d&)>& sample,
                                  const std::function<double(double cos_theta)>& pdf, long samples,
                                  std::uint64_t seed = 1234567) {
  constexpr int kTheta = 40, kPhi = 4;
  std::vector<double> observed(kTheta * kPhi + 1, 0.0), expected(kTheta * kPhi + 1, 0.0);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (long i = 0; i < samples; ++i) {
    const Vec3d m = sample(Vec2d(uni(rng), uni(rng)));
    if (!(m.z() >= 0.0) || !std::isfinite(m.z())) {
      observed.back() += 1;
      continue;
    }
    const double th = std::acos(std::clamp(m.z(), -1.0, 1.0));
    const double t = std::pow(th / (kPi / 2), 0.25);
    const int it = std::clamp(int(t * kTheta), 0, kTheta - 1);
    double ph = std::atan2(m.y(), m.x());
    if (ph < 0) ph += 2 * kPi;
    const int ip = std::clamp(int(ph / (2 * kPi) * kPhi), 0, kPhi - 1);
    observed[it * kPhi + ip] += 1;
  }
  double total = 0.0;
  for (int it = 0; it < kTheta; ++it) {
    const double mass = integrate_over_theta(pdf, double(it) / kTheta, double(it + 1) / kTheta, 2);
    total += mass;
    for (int ip = 0; ip < kPhi; ++ip) expected[it * kPhi + ip] = samples * mass / kPhi;
  }
  expected.back() = std::max(0.0, samples * (1.0 - total));
  // Pool consecutive bins until each expects ≥ 5; the missed-mass bin joins the last pool.
  std::vector<double> o, e;
  double ao = 0, ae = 0;
  for (std::size_t i = 0; i < observed.size(); ++i) {
    ao += observed[i];
    ae += expected[i];
    if (ae >= 5.0) {
      o.push_back(ao);
      e.push_back(ae);
      ao = ae = 0;
    }
  }
  if (!o.empty()) {
    o.back() += ao;
    e.back() += ae;
  }
  Chi2Outcome r;
  for (std::size_t i = 0; i < o.size(); ++i) {
    const double d = o[i] - e[i];
    r.statistic += e[i] > 0 ? d * d / e[i] : (o[i] > 0 ? 1e300 : 0.0);
  }
  r.dof = int(o.size()) - 1;
  if (r.dof < 1) return r;
  boost::math::chi_squared_distribution<double> dist(r.dof);
  r.p_value = r.statistic > 1e200 ? 0.0 : boost::math::cdf(boost::math::complement(dist, r.statistic));
  return r;
}

// D, P22 and unit in ceres::Jet equal the double evaluation, and their parameter derivatives match
// fourth-order central differences to 1e-6 relative (DESIGN.md §1: one template for doubles and Jets).
template <template <class> class N> void expect_jets(std::vector<double> p, std::vector<double> cosines = {0.3, 0.8, 0.97, 0.999}) {
  using J = ceres::Jet<double, 3>;
  std::vector<J> pj;
  for (std::size_t i = 0; i < p.size(); ++i) pj.emplace_back(p[i], int(i));
  const N<J> dj(pj.data());
  const N<double> d(p.data());
  const std::string name = test::describe_params(p);
  for (double c : cosines) {
    const double x = (1 - c * c) / (c * c);
    if (!(d.D(c) > 1e-200)) continue;  // the far tail, down to subnormal numbers: nothing to compare
    const J Dj = dj.D(J(c)), Pj = dj.P22(J(x)), Uj = dj.unit(J(c));
    EXPECT_NEAR(Dj.a, d.D(c), 1e-13 * std::abs(d.D(c))) << name << " c " << c;
    EXPECT_NEAR(Pj.a, d.P22(x), 1e-13 * std::abs(d.P22(x))) << name << " c " << c;
    EXPECT_NEAR(Uj.a, d.unit(c), 1e-13 * std::abs(d.unit(c))) << name << " c " << c;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double h = 1e-5 * std::abs(p[i]);
      auto at = [&](double delta) {
        std::vector<double> q = p;
        q[i] += delta;
        const N<double> e(q.data());
        return std::array<double, 3>{e.D(c), e.P22(x), e.unit(c)};
      };
      // Fourth-order central difference: steep exponentials (e^{−x/α²}) defeat the 2nd-order one.
      const auto h1 = at(h), l1 = at(-h), h2 = at(2 * h), l2 = at(-2 * h), mid = at(0);
      // A kink in the parameter (a compact support's edge reaching c) has no derivative to compare.
      if (std::abs((h1[0] - mid[0]) - (mid[0] - l1[0])) > 1e-3 * std::abs(h1[0] - l1[0])) continue;
      double fd[3];
      for (int k = 0; k < 3; ++k) fd[k] = (8 * (h1[k] - l1[k]) - (h2[k] - l2[k])) / (12 * h);
      const double ad[3] = {Dj.v[i], Pj.v[i], Uj.v[i]};
      const double scale[3] = {d.D(c), d.P22(x), d.unit(c)};
      for (int k = 0; k < 3; ++k) {
        // Relative to the derivative, or to value/parameter where the derivative nearly vanishes.
        const double tol = 1e-6 * std::max(std::abs(fd[k]), 1e-3 * std::abs(scale[k] / p[i]));
        EXPECT_NEAR(ad[k], fd[k], tol) << name << " c " << c << " param " << i << " (D, P22, unit)[" << k << "]";
      }
    }
  }
}

}  // namespace brdfkit::test
