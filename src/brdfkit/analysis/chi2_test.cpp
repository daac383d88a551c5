#include "brdfkit/analysis/chi2_test.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "brdfkit/core/sphere_integral.h"

namespace brdfkit {

namespace {

struct Bin {
  double observed, expected;
};

// Pearson statistic with Mitsuba's pooling (chi2 in mitsuba/core/math.h): bins sorted by
// expected count; those below the threshold accumulate into a pool that becomes a bin once
// it reaches the threshold. A final pool that never reaches it joins the last pooled bin (or
// stands alone) rather than being dropped, so every draw counts.
void pearson(std::vector<Bin> bins, double threshold, Chi2Result& r) {
  std::sort(bins.begin(), bins.end(), [](const Bin& a, const Bin& b) { return a.expected < b.expected; });
  std::vector<Bin> merged;
  Bin pool{0, 0};
  int pool_count = 0;
  for (const Bin& b : bins) {
    if (b.expected <= 0) continue;  // zero-expectation cells are checked separately
    if (b.expected < threshold) {
      pool.observed += b.observed;
      pool.expected += b.expected;
      ++pool_count;
      ++r.pooled_in;
      if (pool.expected >= threshold) {
        merged.push_back(pool);
        ++r.pooled_out;
        pool = {0, 0};
        pool_count = 0;
      }
    } else {
      merged.push_back(b);
    }
  }
  if (pool_count > 0) {
    if (r.pooled_out > 0) {
      // merged is sorted by construction only among pooled bins; the first pooled bins are at the front.
      merged[size_t(r.pooled_out - 1)].observed += pool.observed;
      merged[size_t(r.pooled_out - 1)].expected += pool.expected;
    } else {
      merged.push_back(pool);
      ++r.pooled_out;
    }
  }
  r.statistic = 0;
  for (const Bin& b : merged) r.statistic += (b.observed - b.expected) * (b.observed - b.expected) / b.expected;
  r.dof = int(merged.size()) - 1;
}

// Draws sorted into the (cosθ, φ) cells, with the draws the sampler rejected and those that are
// not unit directions above the horizon.
struct Draws {
  std::vector<double> observed;
  long rejected = 0, invalid = 0;
};
Draws draw(const DirectionSampler& sample, const Chi2Options& o) {
  const int nt = o.cos_theta_cells, np = o.phi_cells;
  Draws out{std::vector<double>(size_t(nt * np), 0.0)};
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (long k = 0; k < o.samples; ++k) {
    const double u0 = uniform(rng), u1 = uniform(rng), ul = uniform(rng);
    const auto w = sample(Vec2d(u0, u1), ul);
    if (!w) {
      ++out.rejected;
      continue;
    }
    const Vec3d& d = *w;
    if (!d.allFinite() || std::abs(d.norm() - 1) > 1e-6 || !(d.z() > 0)) {
      ++out.invalid;
      continue;
    }
    const int it = std::min(nt - 1, int(d.z() * nt));
    const int ip = std::clamp(int((std::atan2(d.y(), d.x()) + kPi) / (2 * kPi) * np), 0, np - 1);
    out.observed[size_t(it * np + ip)] += 1;
  }
  return out;
}

// Expected counts: N ∫ pdf over each (cosθ, φ) cell; dω = dcosθ dφ.
std::vector<double> expected_counts(const DirectionPdf& pdf, const Chi2Options& o) {
  const int nt = o.cos_theta_cells, np = o.phi_cells;
  std::vector<double> expected(size_t(nt * np), 0.0);
  tbb::parallel_for(0, nt, [&](int it) {
    for (int ip = 0; ip < np; ++ip) {
      const double c0 = double(it) / nt, c1 = double(it + 1) / nt;
      const double p0 = -kPi + 2 * kPi * ip / np, p1 = -kPi + 2 * kPi * (ip + 1) / np;
      const auto f = [&](double ct, double phi) {
        const double st = std::sqrt(std::max(0.0, 1 - ct * ct));
        return pdf(Vec3d(st * std::cos(phi), st * std::sin(phi), ct));
      };
      expected[size_t(it * np + ip)] = double(o.samples) * integrate_rect(f, c0, c1, p0, p1, o.quadrature_tol, 8);
    }
  });
  return expected;
}

// Second test: P(rejected) = 1 − ∫ pdf. Binomial σ with the pdf's prediction; a floor of one
// draw's worth keeps σ > 0 when nothing is rejected, plus the quadrature tolerance.
void integral_test(double n, double level, double quadrature_tol, Chi2Result& r, std::string& why) {
  const double q = std::clamp(1.0 - r.pdf_integral, 1.0 / n, 1.0 - 1.0 / n);
  const double sigma = std::sqrt(q * (1 - q) / n) + 10 * quadrature_tol;
  r.integral_z = (1.0 - r.pdf_integral - r.rejected_fraction) / sigma;
  r.integral_p_value = 2 * boost::math::cdf(boost::math::complement(boost::math::normal(), std::abs(r.integral_z)));
  r.integral_passed = r.integral_p_value >= level && r.pdf_integral <= 1 + 1e-3;
  if (!r.integral_passed)
    why += fmt::format("pdf integral {:.6f} disagrees with the rejected fraction {:.6f} (z = {:.2f}); ",
                       r.pdf_integral, r.rejected_fraction, r.integral_z);
}

}  // namespace

Chi2Result chi2_test(const DirectionSampler& sample, const DirectionPdf& pdf, const Chi2Options& o) {
  Chi2Result r;
  const double n = double(o.samples);
  const Draws d = draw(sample, o);
  const std::vector<double> expected = expected_counts(pdf, o);

  r.pdf_integral = std::accumulate(expected.begin(), expected.end(), 0.0) / n;
  r.rejected_fraction = double(d.rejected) / n;
  std::string why;
  const double min_expected = *std::min_element(expected.begin(), expected.end());
  if (!(min_expected >= 0)) why += fmt::format("a cell has a negative or NaN pdf integral ({:g}); ", min_expected / n);
  if (!(r.pdf_integral <= 1 + 1e-3)) why += fmt::format("the pdf integrates to {:.6f} > 1; ", r.pdf_integral);
  if (d.invalid > 0) why += fmt::format("{} draws were not unit directions above the horizon; ", d.invalid);
  for (size_t k = 0; k < expected.size(); ++k)
    if (expected[k] == 0 && d.observed[k] > 0) {
      why += "draws landed in a cell of zero density; ";
      break;
    }

  std::vector<Bin> bins;
  for (size_t k = 0; k < expected.size(); ++k)
    bins.push_back({d.observed[k], std::isfinite(expected[k]) ? std::max(0.0, expected[k]) : 0.0});
  const double expected_rejected = n * std::max(0.0, 1.0 - r.pdf_integral);
  if (expected_rejected > 0 || d.rejected > 0) bins.push_back({double(d.rejected), expected_rejected});
  if (expected_rejected == 0 && d.rejected > 0) why += "draws were rejected but the pdf integrates to 1; ";
  pearson(bins, o.min_expected, r);
  if (r.dof < 1) why += "too few degrees of freedom; ";
  if (r.dof >= 1 && std::isfinite(r.statistic)) {
    r.p_value = boost::math::cdf(boost::math::complement(boost::math::chi_squared(r.dof), r.statistic));
  } else {
    r.p_value = 0;
  }
  // Šidák correction: the family of test_count tests keeps the requested significance.
  const double level = 1 - std::pow(1 - o.significance, 1.0 / std::max(1, o.test_count));
  integral_test(n, level, o.quadrature_tol, r, why);
  if (!(r.p_value >= level))
    why += fmt::format("chi2 = {:.1f} with {} dof: p = {:.3g} < {:.3g}; ", r.statistic, r.dof, r.p_value, level);
  r.passed = why.empty();
  if (!why.empty()) why.resize(why.size() - 2);
  r.message = why;
  return r;
}

Chi2Result chi2_test(const Model& model, const double* p, int c, const Vec3d& wo, const Chi2Options& options) {
  return chi2_test([&](const Vec2d& u, double ul) { return model.sample(p, c, wo, u, ul); },
                   [&](const Vec3d& wi) { return model.pdf(p, c, wo, wi); }, options);
}

}  // namespace brdfkit
