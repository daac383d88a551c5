// The `he` model (He, Torrance, Sillion & Greenberg 1991): its physical limits, reciprocity,
// Jets, sampling and albedo at the parameter bounds.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>

#include "brdfkit/analysis/chi2_test.h"
#include "brdfkit/analysis/model_checks.h"
#include "brdfkit/models/he_torrance.h"
#include "brdfkit/ndf/beckmann.h"
#include "support/mc_albedo.h"
#include "support/output_lines.h"
#include "support/test_util.h"

namespace brdfkit {
namespace {

using P = std::array<double, 6>;  // kd, ks, sigma0 (µm), tau (µm), eta, k

// Aluminium at the green channel's 0.526 µm: n + ik ≈ 0.96 + 6.69i (Rakić 1995; He 1991
// models aluminium surfaces with such an index).
constexpr double kAlEta = 0.96, kAlK = 6.69;

const ModelAdapter<HeTorrance>& model() {
  static const ModelAdapter<HeTorrance> m;
  return m;
}

// The rough limit (He 1991 §4: for g ≫ 1 the directional-diffuse term becomes the geometrical-
// optics reflection of a Gaussian slope distribution): ρ_dd → F S D_Beckmann / (4 cosθi cosθr)
// with α = 2σ/τ (σ the effective roughness). A rough aluminium, σ0 = 1 µm, τ = 10 µm (α = 0.2),
// red channel: g ≈ 380 at normal incidence, so the O(1/g) remainder is about 1 %.
TEST(He, RoughLimitIsCookTorranceBeckmann) {
  const P p{0.0, 1.0, 1.0, 10.0, kAlEta, kAlK};
  double worst = 0;
  int compared = 0;
  for (double ti_deg : {0.0, 30.0, 60.0}) {
    const Vec3d wi = spherical_direction(ti_deg * kPi / 180, kPi);
    for (double dth = -0.3; dth <= 0.3 + 1e-9; dth += 0.05) {
      for (double phi : {0.0, 0.15}) {
        const double to = ti_deg * kPi / 180 + dth;
        if (!(to > 0.02 && to < 1.45)) continue;
        const Vec3d wo = spherical_direction(to, phi);
        const Vec3d h = (wi + wo).normalized();
        const double sigma = he_effective_roughness(wi.z(), wo.z(), p[2], p[3]);
        const double alpha = 2 * sigma / p[3];
        const double ct = ConductorFresnel<double>(p.data() + 4).eval(wi.dot(h)) * he_shadowing(wi.z(), p[2], p[3]) *
                          he_shadowing(wo.z(), p[2], p[3]) * Beckmann<double>(&alpha).D(h.z()) /
                          (4 * wi.z() * wo.z());
        if (ct < 1e-2 * Beckmann<double>(&alpha).D(1.0) / 4) continue;  // the lobe, not its far tail
        const double he = model().eval(p.data(), 0, wi, wo);
        worst = std::max(worst, std::fabs(he / ct - 1));
        ++compared;
        EXPECT_NEAR(he / ct, 1.0, 0.03) << "theta_i " << ti_deg << " theta_o " << to << " phi " << phi;
      }
    }
  }
  EXPECT_GT(compared, 20);
  std::printf("[ he rough ] %d directions, worst |rho_he/rho_CT-Beckmann - 1| = %.4f\n", compared, worst);
}

// Energy (He 1991 abstract and §5: "self consistent in terms of ... energy"): for gentle slopes
// the spike takes e^{−g} of the Fresnel reflectance and the directional-diffuse lobe the rest,
// so spike + ∫ρ_dd cos = F(θi). Polished aluminium, σ0 = 0.05 µm, τ = 5 µm (slopes α = 0.02),
// green channel: g ≈ 1.4 at normal incidence, i.e. a quarter in the spike and three quarters
// scattered into a lobe of ~1°.
TEST(He, SpikePlusDirectionalDiffuseEqualsFresnel) {
  const P p{0.0, 1.0, 0.05, 5.0, kAlEta, kAlK};
  for (double deg : {0.0, 30.0, 50.0}) {
    const double t = deg * kPi / 180;
    const double fresnel = ConductorFresnel<double>(p.data() + 4).eval(std::cos(t));
    const double spike = HeTorrance::specular_reflectance(p.data(), 1, std::cos(t));
    const double dd = albedo(model(), p.data(), 1, t, 1e-4);
    std::printf("[ he energy ] theta_i %2.0f: spike %.4f + directional diffuse %.4f = %.4f, F = %.4f\n", deg, spike,
                dd, spike + dd, fresnel);
    EXPECT_NEAR(spike + dd, fresnel, 0.01 * fresnel) << deg;
    if (deg == 0.0) {
      EXPECT_NEAR(spike / fresnel, std::exp(-std::pow(4 * kPi * 0.05 / 0.526, 2)), 1e-12);
    }
  }
}

std::vector<P> parameter_sets() {
  return {
      {0.2, 1.0, 0.18, 3.0, 1.5, 0.0},         // defaults: a dielectric
      {0.0, 1.0, 0.4, 2.0, kAlEta, kAlK},      // rough aluminium
      {0.1, 0.7, 0.02, 5.0, 1.3, 2.0},         // nearly smooth, g < 0.1
      {0.3, 1.0, 1.5, 1.0, 1.8, 0.0},          // very rough, α = 3
  };
}

TEST(He, ReciprocalTo1e10) {
  for (const P& p : parameter_sets()) {
    for (int c = 0; c < 3; ++c) {
      const ReciprocityCheck r = reciprocity_check(model(), p.data(), c, 2000, 17);
      EXPECT_GT(r.pairs, 1000);
      EXPECT_LE(r.max_relative_error, 1e-10) << "sigma0 " << p[2] << " tau " << p[3] << " channel " << c;
    }
  }
}

TEST(He, FiniteNonNegativeAndZeroBelowTheHorizon) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const P& p : parameter_sets()) {
    EXPECT_EQ(model().eval(p.data(), 0, Vec3d(0, 0.6, -0.8), Vec3d::UnitZ()), 0.0);
    EXPECT_TRUE(std::isfinite(model().eval(p.data(), 0, Vec3d::UnitZ(), Vec3d::UnitZ())));
    for (int k = 0; k < 2000; ++k) {
      const Vec3d wi = spherical_direction(std::acos(u(rng)), 2 * kPi * u(rng));
      const Vec3d wo = spherical_direction(std::acos(u(rng)), 2 * kPi * u(rng));
      const double f = model().eval(p.data(), int(k % 3), wi, wo);
      ASSERT_TRUE(std::isfinite(f) && f >= 0) << f;
    }
  }
}

// Jets (automatic differentiation through the series, the effective roughness's root and erfc)
// against central differences. The series' term count may change between the two evaluations
// of a difference, a jump ≤ 10⁻⁶ ρ_dd; the step 10⁻³ keeps its effect on the quotient ≤ 5·10⁻⁴.
TEST(He, JetsMatchCentralDifferences) {
  using Jet = ceres::Jet<double, 6>;
  const std::vector<P> sets{{0.1, 0.8, 0.2, 2.5, 1.3, 3.0}, {0.1, 0.8, 0.03, 4.0, 1.6, 0.5}, {0.1, 0.8, 0.9, 3.0, 0.9, 6.0}};
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0;
  for (const P& p : sets) {
    for (int n = 0; n < 30; ++n) {
      const int c = n % 3;
      const Vec3d wi = spherical_direction(std::acos(0.1 + 0.9 * u(rng)), 2 * kPi * u(rng));
      const Vec3d wo = spherical_direction(std::acos(0.1 + 0.9 * u(rng)), 2 * kPi * u(rng));
      std::array<Jet, 6> pj;
      for (int i = 0; i < 6; ++i) pj[i] = Jet(p[i], i);
      const Jet fj = HeTorrance::eval<Jet>(pj.data(), c, wi.cast<Jet>(), wo.cast<Jet>());
      const double fd = HeTorrance::eval<double>(p.data(), c, wi, wo);
      // Jets sum the series; doubles read its table (he_series_table.h), within 1e-6. Summed in
      // doubles too (a statistics pointer takes the series), the two differ by rounding only.
      HeSeriesStats stats;
      const double summed = p[0] * kInvPi + p[1] * HeTorrance::directional_diffuse<double>(p.data(), c, wi, wo, &stats);
      ASSERT_NEAR(fj.a, summed, 1e-12 * summed);  // Jet arithmetic rounds differently
      ASSERT_NEAR(fd, summed, 1e-6 * summed);
      for (int i = 0; i < 6; ++i) {
        const double h = 1e-3 * std::abs(p[i]);
        P lo = p, hi = p;
        lo[i] -= h;
        hi[i] += h;
        const double diff =
            (HeTorrance::eval<double>(hi.data(), c, wi, wo) - HeTorrance::eval<double>(lo.data(), c, wi, wo)) / (2 * h);
        const double scale = std::abs(diff) + fd / std::abs(p[i]);
        EXPECT_NEAR(fj.v[i], diff, 2e-3 * scale) << "d/d" << HeTorrance::params()[i].name << " set sigma0 " << p[2];
        worst = std::max(worst, std::abs(fj.v[i] - diff) / scale);
      }
    }
  }
  std::printf("[ he jets ] worst |jet - central difference| / scale = %.3g\n", worst);
}

// χ² goodness of fit of the sampler against its pdf (analysis/chi2_test.h), normal to grazing.
TEST(He, SamplingChi2) {
  const double incidences[] = {10.0, 55.0, 86.0};
  Chi2Options o;
  o.samples = 100000;
  o.test_count = int(parameter_sets().size() * std::size(incidences));
  for (const P& p : parameter_sets()) {
    for (double deg : incidences) {
      const Vec3d wo = spherical_direction(deg * kPi / 180, 0.3);
      const Chi2Result r = chi2_test(model(), p.data(), 1, wo, o);
      EXPECT_TRUE(r.passed) << "sigma0 " << p[2] << " tau " << p[3] << " theta_o " << deg << ": " << r.message
                            << " chi2 " << r.statistic << " dof " << r.dof << " p " << r.p_value;
      EXPECT_LE(r.pdf_integral, 1 + 1e-6);
      std::printf("[ he chi2 ] sigma0 %.2f tau %.1f theta_o %2.0f: p = %.3f, int pdf = %.5f, rejected %.4f\n", p[2],
                  p[3], deg, r.p_value, r.pdf_integral, r.rejected_fraction);
    }
  }
}

TEST(He, SamplingChi2FailsWithPdfTimesTwo) {
  for (const P& p : parameter_sets()) {
    const Vec3d wo = spherical_direction(0.7, 0.3);
    Chi2Options o;
    o.samples = 20000;
    const auto r = chi2_test([&](const Vec2d& u, double ul) { return model().sample(p.data(), 1, wo, u, ul); },
                             [&](const Vec3d& wi) { return 2 * model().pdf(p.data(), 1, wo, wi); }, o);
    EXPECT_FALSE(r.passed);
    EXPECT_FALSE(r.integral_passed);
  }
}

// Albedo at the corners of the parameter box the CLI accepts (colours at their upper bound):
// finite everywhere; where it exceeds 1 is printed, not clamped.
TEST(He, AlbedoFiniteAtParameterBounds) {
  const ParamTable t = HeTorrance::params();
  double worst = 0;
  std::string worst_where;
  for (int corner = 0; corner < 16; ++corner) {
    P p{0.0, t[1].upper, 0, 0, 0, 0};
    for (int i = 0; i < 4; ++i) p[2 + i] = (corner >> i) & 1 ? t[2 + i].upper : t[2 + i].lower;
    for (double deg : {0.0, 45.0, 80.0, 89.0}) {
      const double a = test::mc_albedo(model(), p.data(), 0, deg * kPi / 180, 24);
      const double spike = HeTorrance::specular_reflectance(p.data(), 0, std::cos(deg * kPi / 180));
      ASSERT_TRUE(std::isfinite(a) && a >= 0 && std::isfinite(spike)) << corner << " " << deg;
      if (a + spike > worst) {
        worst = a + spike;
        worst_where = "sigma0 " + std::to_string(p[2]) + " tau " + std::to_string(p[3]) + " eta " +
                      std::to_string(p[4]) + " k " + std::to_string(p[5]) + " theta " + std::to_string(int(deg));
      }
    }
  }
  std::printf("[ he albedo ] max over bounds (ks = %.0f, kd = 0) %.4f at %s\n", t[1].upper, worst, worst_where.c_str());
}

// `models` lists He as a line led by its name, followed by one line per parameter of its table.
TEST(He, ListedByTheCli) {
  const auto r = test::run_cli("models");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const auto lines = test::lines_of(r.out);
  const auto at = std::find_if(lines.begin(), lines.end(), [](const std::string& l) {
    const auto t = test::tokens_of(l);
    return t.size() >= 2 && t[0] == "he" && t[1] == "—";
  });
  ASSERT_NE(at, lines.end()) << r.out;
  const ParamTable& table = model().params();
  ASSERT_GT(size_t(lines.end() - at), table.size()) << "fewer lines than parameters\n" << r.out;
  for (size_t i = 0; i < table.size(); ++i) {
    const auto t = test::tokens_of(*(at + 1 + long(i)));
    EXPECT_EQ(t.empty() ? "" : t[0], table[i].name) << "parameter row " << i;
  }
}

}  // namespace
}  // namespace brdfkit
