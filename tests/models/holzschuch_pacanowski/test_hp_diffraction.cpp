// Holzschuch & Pacanowski 2015 (seed 004 Eq. 24–27): the energy normalization E_{a,λ} of the
// diffraction lobe checked by quadrature (the printed value does not normalize it), the
// diffraction lobe and the full model against a separate transcription of the paper's
// equations in half/difference angles (Eq. 11 for f, Eq. 26 for D, Eq. 27 for F, G1 from the
// direct Smith integral rather than the §5.5 table the model interpolates).
#include <gtest/gtest.h>

#include <boost/math/special_functions/gamma.hpp>
#include <random>

#include "brdfkit/analysis/model_checks.h"
#include "brdfkit/core/sphere_integral.h"
#include "brdfkit/core/half_diff.h"
#include "brdfkit/models/holzschuch_pacanowski.h"
#include "brdfkit/models/hp_diffraction_lobe.h"
#include "brdfkit/shadowing/exponential_power_g1.h"

namespace brdfkit {
namespace {

// Sz(f) (Eq. 16/25) with f = (2/λ) sinθh cosθd (Eq. 11).
double paper_sz(double a, double lambda, double theta_h, double theta_d) {
  const double f = 2 / lambda * std::sin(theta_h) * std::cos(theta_d);
  const double q = 1 + f * f / (a * a);
  return 1 / (q * q);
}

// ∫ g(wo) cosθo dωo over the hemisphere for wi at θi (φ = 0), with fine cells around the
// mirror direction, where the lobe peaks.
template <class G> double hemisphere_integral(G&& g, double theta_i) {
  auto f = [&](double t, double ph) { return g(spherical_direction(t, ph)) * std::cos(t) * std::sin(t); };
  const auto ts = breakpoints(0.0, kPi / 2, 16, {theta_i}, 1e-3);
  const auto ps = breakpoints(-kPi, kPi, 16, {0.0}, 1e-3);
  return integrate_grid(f, ts, ps, 1e-9);
}

// E_{a,λ} = ∫ Sz cosθo dωo at normal incidence (its maximum over θi): the corrected
// π/(1 + 1/(a²λ²)) normalizes the lobe; the printed π(1 + 1/(a²λ²)) leaves 1/(1 + 1/(a²λ²))².
TEST(HpDiffraction, EnergyNormalization) {
  for (double a : {0.3, 0.91, 1.4, 5.0}) {
    for (int c = 0; c < 3; ++c) {
      const double lambda = kChannelWavelengthUm[c];
      const HpDiffractionLobe<double> lobe{a, lambda};
      const Vec3d n = Vec3d::UnitZ();
      const double e = hemisphere_integral([&](const Vec3d& wo) { return lobe.sz(n, wo); }, 0.0);
      EXPECT_NEAR(e / lobe.energy(), 1.0, 1e-7) << "a " << a << " lambda " << lambda;
      const double printed = e / lobe.printed_energy();
      const double k2 = a * a * lambda * lambda;
      EXPECT_NEAR(printed, 1 / ((1 + 1 / k2) * (1 + 1 / k2)), 1e-7) << "a " << a << " lambda " << lambda;
      if (a == 0.91 && c == 0) {
        std::cout << "[ E_a,l    ] a 0.91, lambda 0.645: int Sz cos dw = " << e << ", corrected E = " << lobe.energy()
                  << ", printed E = " << lobe.printed_energy() << " -> albedo with printed E " << printed << "\n";
        RecordProperty("int_sz_a0.91_red", std::to_string(e));
        RecordProperty("albedo_printed_E_a0.91_red", std::to_string(printed));
      }
      // Normal incidence is the maximum: oblique incidence reflects less.
      for (double ti : {0.5, 1.0, 1.4}) {
        const Vec3d wi = spherical_direction(ti, 0.0);
        const double ei = hemisphere_integral([&](const Vec3d& wo) { return lobe.sz(wi, wo); }, ti);
        EXPECT_LT(ei, e) << "a " << a << " theta_i " << ti;
      }
    }
  }
}

// HpDiffractionLobe (Eq. 10's projected form) against Eq. 11 in angles, divided by the E above.
TEST(HpDiffraction, LobeMatchesEq11InHalfDiffAngles) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0;
  for (double a : {0.05, 0.91, 3.0}) {
    for (int c = 0; c < 3; ++c) {
      const double lambda = kChannelWavelengthUm[c];
      const double k2 = a * a * lambda * lambda;
      const double e = kPi / (1 + 1 / k2);
      const HpDiffractionLobe<double> lobe{a, lambda};
      for (int k = 0; k < 200; ++k) {
        const HalfDiff hd{std::acos(u(rng)), 2 * kPi * u(rng), std::acos(u(rng)), 2 * kPi * u(rng)};
        Vec3d wi, wo;
        from_half_diff(hd, wi, wo);
        const double want = paper_sz(a, lambda, hd.theta_h, hd.theta_d) / e;
        worst = std::max(worst, std::abs(lobe.eval(wi, wo) - want) / want);
      }
    }
  }
  EXPECT_LT(worst, 1e-10);
  RecordProperty("worst_relative_difference", std::to_string(worst));
}

struct HpParams {
  double kd, ks, kw, sigma, p, a, f0;
};

// Eq. 24 with Eq. 25–27 in θh, θd; G1 = 1/(1 + Λ(σ tanθ)) from the direct integral of Eq. 20–21.
double paper_eq24(const HpParams& q, int c, double theta_h, double theta_d, double theta_i, double theta_o) {
  const double lambda = kChannelWavelengthUm[c];
  const double t2 = std::tan(theta_h) * std::tan(theta_h);
  const double d = q.p / (kPi * q.sigma * q.sigma * boost::math::tgamma(1 / q.p)) *
                   std::exp(-std::pow(t2 / (q.sigma * q.sigma), q.p)) / std::pow(std::cos(theta_h), 4);  // Eq. 26
  const double f = q.f0 + (1 - q.f0) * std::pow(1 - std::cos(theta_d), 5);                                // Eq. 27
  const double g = ExponentialPowerG1Table::g1_direct(q.sigma * std::tan(theta_i), q.p) *
                   ExponentialPowerG1Table::g1_direct(q.sigma * std::tan(theta_o), q.p);
  const double k2 = q.a * q.a * lambda * lambda;
  const double e = kPi / (1 + 1 / k2);  // corrected E_{a,λ}
  return q.kd / kPi + g * (q.ks * d * f / (4 * std::cos(theta_i) * std::cos(theta_o)) +
                           q.kw / std::pow(lambda, 4) * paper_sz(q.a, lambda, theta_h, theta_d) / e);
}

// The full model; G1 differs by the §5.5 table's bilinear interpolation error against the direct
// integral: up to 0.8 % on ρ measured here (set 1–3, θ up to acos 0.05), so 1e-2 relative;
// 1e-12 at normal incidence, where G = 1.
TEST(HolzschuchPacanowski, MatchesPaperEq24InHalfDiffAngles) {
  const Model& m = model_by_name("holzschuch-pacanowski");
  const HpParams sets[] = {{0.01, 0.7, 0.05, 0.027, 0.51, 0.91, 0.6},  // nickel's a, σ, p (seed 004 Fig. 12a)
                           {0.2, 1.0, 0.01, 0.2, 1.2, 0.4, 0.04},
                           {0.0, 0.0, 0.03, 0.5, 0.3, 2.0, 0.9}};
  std::mt19937_64 rng(24);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0;
  for (const auto& q : sets) {
    ParamValues v = ParamValues::defaults(m.params());
    const std::pair<const char*, double> set[] = {{"kd", q.kd}, {"ks", q.ks},   {"kw", q.kw}, {"sigma", q.sigma},
                                                  {"p", q.p},   {"a", q.a},     {"F0", q.f0}};
    for (const auto& [name, value] : set) v.set(m.params(), name, value);
    for (int c = 0; c < 3; ++c) {
      const Vec3d n = Vec3d::UnitZ();
      EXPECT_NEAR(m.eval(v.channel(c), c, n, n), paper_eq24(q, c, 0, 0, 0, 0), 1e-12 * paper_eq24(q, c, 0, 0, 0, 0));
      for (int k = 0; k < 40; ++k) {
        const HalfDiff hd{std::acos(u(rng)) * 0.9, 2 * kPi * u(rng), std::acos(u(rng)) * 0.9, 2 * kPi * u(rng)};
        Vec3d wi, wo;
        from_half_diff(hd, wi, wo);
        if (!(wi.z() > 0.05 && wo.z() > 0.05)) continue;
        const double want = paper_eq24(q, c, hd.theta_h, hd.theta_d, std::acos(wi.z()), std::acos(wo.z()));
        const double got = m.eval(v.channel(c), c, wi, wo);
        worst = std::max(worst, std::abs(got - want) / want);
        EXPECT_NEAR(got, want, 1e-2 * want) << "c " << c << " theta_h " << hd.theta_h << " theta_d " << hd.theta_d;
      }
    }
  }
  RecordProperty("worst_relative_difference", std::to_string(worst));
  std::cout << "[ eq24     ] worst relative difference (G1 table vs direct integral) " << worst << "\n";
}

// The diffraction lobe alone, kw = λ⁴: albedo 1 at normal incidence without masking, so with
// G it reflects a little less than 1 (quadrature of the model through analysis/model_checks).
TEST(HolzschuchPacanowski, DiffractionAlbedoAtNormalIncidence) {
  const Model& m = model_by_name("holzschuch-pacanowski");
  for (int c = 0; c < 3; ++c) {
    ParamValues v = ParamValues::defaults(m.params());
    const double l = kChannelWavelengthUm[c];
    v.set(m.params(), "kd", 0.0);
    v.set(m.params(), "ks", 0.0);
    v.set(m.params(), "kw", l * l * l * l);
    v.set(m.params(), "sigma", 0.05);
    v.set(m.params(), "a", 0.91);
    const double a0 = albedo(m, v.channel(c), c, 0.0);
    std::cout << "[ albedo   ] diffraction lobe, kw = lambda^4, a 0.91, sigma 0.05, c" << c << ": " << a0 << "\n";
    EXPECT_LT(a0, 1.0);
    EXPECT_GT(a0, 0.95);
  }
}

}  // namespace
}  // namespace brdfkit
