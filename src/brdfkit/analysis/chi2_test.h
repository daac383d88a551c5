#pragma once
// Pearson χ² test of a sampling routine against its density, in the manner of Mitsuba 3's
// chi2.py (ChiSquareTest with SphericalDomain): draw N directions, histogram them on a
// (cosθ, φ) grid of the upper hemisphere (equal solid-angle cells), integrate the pdf over
// each cell by adaptive quadrature for the expected counts, pool cells expected below 5,
// and compare. Draws the sampler rejects (nullopt) form one more cell whose expected count is
// N (1 − ∫ pdf dω): a pdf whose integral disagrees with the rejected mass fails too.
//
// A second, separate test compares that integral with the rejected fraction alone
// ("pdf against the numerically integrated density"): 1 − ∫ pdf = P(rejected), a binomial z.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "brdfkit/core/vec.h"
#include "brdfkit/models/model.h"

namespace brdfkit {

struct Chi2Options {
  int cos_theta_cells = 20;    // cells over cosθ ∈ [0, 1]
  int phi_cells = 40;          // cells over φ ∈ [−π, π]
  long samples = 200000;       // N
  std::uint64_t seed = 5489;   // std::mt19937_64 seed
  double min_expected = 5.0;   // cells expected below this are pooled (Mitsuba's threshold)
  double significance = 0.01;  // reject when p < significance (before any correction)
  int test_count = 1;          // Šidák correction when a caller runs several tests
  double quadrature_tol = 1e-7;
};

struct Chi2Result {
  double statistic = 0;          // Pearson χ²
  int dof = 0;                   // bins − 1
  double p_value = 0;            // P(χ²_dof ≥ statistic)
  int pooled_in = 0;             // low-expectation cells pooled …
  int pooled_out = 0;            // … into this many bins
  double pdf_integral = 0;       // ∫ pdf dω over the hemisphere (quadrature)
  double rejected_fraction = 0;  // draws the sampler returned as nullopt
  double integral_z = 0;         // (1 − pdf_integral − rejected_fraction) / binomial σ
  double integral_p_value = 0;   // two-sided p of integral_z
  bool integral_passed = false;  // second test: pdf integral against the rejected mass
  bool passed = false;           // χ² test and the integral test and no sanity failure
  std::string message;           // why it failed (empty when it passed)
};

using DirectionSampler = std::function<std::optional<Vec3d>(const Vec2d& u, double u_lobe)>;
using DirectionPdf = std::function<double(const Vec3d& w)>;

Chi2Result chi2_test(const DirectionSampler& sample, const DirectionPdf& pdf, const Chi2Options& options = {});

// The model's sampling of wi given wo, for channel c with values p.
Chi2Result chi2_test(const Model& model, const double* p, int c, const Vec3d& wo, const Chi2Options& options = {});

}  // namespace brdfkit
