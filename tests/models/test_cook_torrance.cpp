#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <tuple>

#include "brdfkit/analysis/model_checks.h"
#include "brdfkit/models/cook_torrance_catalogue.h"
#include "brdfkit/models/model.h"
#include "support/param_sets.h"

using namespace brdfkit;

namespace {

template <class F> void for_each_cook_torrance(F&& f) {
  std::apply([&](auto... m) { (f(m), ...); }, CookTorranceCatalogue{});
}

Vec3d random_direction(std::mt19937_64& rng, double max_theta_deg = 80) {
  std::uniform_real_distribution<double> u(0, 1);
  const double cos_max = std::cos(max_theta_deg * kPi / 180);
  return spherical_direction(std::acos(cos_max + (1 - cos_max) * u(rng)), 2 * kPi * u(rng));
}

// Independent transcription of seed 004 Eq. 1 with Beckmann D, its closed-form Λ (DESIGN.md §4)
// and Schlick's F, from angles rather than the model's code path.
double reference_beckmann_schlick(double kd, double ks, double alpha, double f0, const Vec3d& wi, const Vec3d& wo) {
  const Vec3d h = (wi + wo).normalized();
  const double th = std::acos(h.z()), cd = wi.dot(h);
  const double D = std::exp(-std::pow(std::tan(th) / alpha, 2)) / (kPi * alpha * alpha * std::pow(std::cos(th), 4));
  auto lambda = [&](const Vec3d& w) {
    const double a = 1 / (alpha * std::tan(std::acos(w.z())));
    return (std::erf(a) - 1) / 2 + std::exp(-a * a) / (2 * a * std::sqrt(kPi));
  };
  const double G = 1 / (1 + lambda(wi)) / (1 + lambda(wo));
  const double F = f0 + (1 - f0) * std::pow(1 - cd, 5);
  return kd / kPi + ks * F * D * G / (4 * wi.z() * wo.z());
}

}  // namespace

TEST(CookTorrance, ParamTableOrder) {
  const ParamTable t = CookTorranceGgx::params();
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t[0].name, "kd");
  EXPECT_TRUE(t[0].linear);
  EXPECT_EQ(t[0].scope, Scope::PerChannel);
  EXPECT_EQ(t[1].name, "ks");
  EXPECT_TRUE(t[1].linear);
  EXPECT_EQ(t[2].name, "alpha");
  EXPECT_EQ(t[3].name, "F0");
  EXPECT_EQ(CookTorranceGgx::fresnel_offset(), 3);
}

TEST(CookTorrance, MatchesSeed004Eq1WithBeckmannAndSchlick) {
  std::mt19937_64 rng(11);
  for (int k = 0; k < 200; ++k) {
    const Vec3d wi = random_direction(rng), wo = random_direction(rng);
    const double p[] = {0.3, 0.8, 0.25, 0.05};
    const double want = reference_beckmann_schlick(p[0], p[1], p[2], p[3], wi, wo);
    EXPECT_NEAR(CookTorranceBeckmann::eval<double>(p, 0, wi, wo), want, 1e-12 * want);
  }
}

TEST(CookTorrance, BagherScaleConversion) {
  // seed 000 Eq. 1: ρd/π + ρs/π · F D G/(cosθi cosθo) equals seed 004 Eq. 1 with ks = 4ρs/π.
  EXPECT_NEAR(ks_from_bagher_rho_s(kPi / 4), 1.0, 1e-15);
  EXPECT_NEAR(bagher_rho_s_from_ks(ks_from_bagher_rho_s(0.37)), 0.37, 1e-15);
  std::mt19937_64 rng(12);
  const double rho_d = 0.2, rho_s = 0.15, alpha = 0.3, f0 = 0.1;
  for (int k = 0; k < 50; ++k) {
    const Vec3d wi = random_direction(rng), wo = random_direction(rng);
    const double fdg_over_cc = (reference_beckmann_schlick(0, 1, alpha, f0, wi, wo)) * 4;  // F D G/(ci co)
    const double bagher = rho_d / kPi + rho_s / kPi * fdg_over_cc;
    const double p[] = {rho_d, ks_from_bagher_rho_s(rho_s), alpha, f0};
    EXPECT_NEAR(CookTorranceBeckmann::eval<double>(p, 0, wi, wo), bagher, 1e-12 * bagher);
  }
}

TEST(CookTorrance, VGrooveMasking) {
  // Ngan's form: G = min(1, 2 cosθh cosθo/(wo·h), 2 cosθh cosθi/(wo·h)), here at a grazing pair
  // where it is below 1.
  const Vec3d wi = spherical_direction(80 * kPi / 180, 0.0), wo = spherical_direction(75 * kPi / 180, 2.0);
  const Vec3d h = (wi + wo).normalized();
  const double g = std::min({1.0, 2 * h.z() * wo.z() / wo.dot(h), 2 * h.z() * wi.z() / wo.dot(h)});
  ASSERT_LT(g, 0.9);
  const double p[] = {0.0, 1.0, 0.4, 1.0};  // F0 = 1: F = 1
  const double D = Beckmann<double>(&p[2]).D(h.z());
  EXPECT_NEAR(CookTorranceNgan::eval<double>(p, 0, wi, wo), D * g / (4 * wi.z() * wo.z()), 1e-12);
}

TEST(CookTorrance, BelowHorizonIsZeroAndNotSampled) {
  for_each_cook_torrance([](auto m) {
    using M = decltype(m);
    const auto vals = ParamValues::defaults(M::params());
    const double* p = vals.channel(0);
    const Vec3d up = spherical_direction(0.3, 0.0), down(0.3, 0.0, -std::sqrt(1 - 0.09));
    EXPECT_EQ(M::template eval<double>(p, 0, up, down), 0.0) << M::name();
    EXPECT_EQ(M::template eval<double>(p, 0, down, up), 0.0) << M::name();
    EXPECT_EQ(M::pdf(p, 0, down, up), 0.0) << M::name();
    EXPECT_FALSE(M::sample(p, 0, down, Vec2d(0.3, 0.4), 0.5).has_value()) << M::name();
  });
}

TEST(CookTorrance, EvalBatchMatchesEval) {
  std::mt19937_64 rng(13);
  SampleSet s;
  for (int k = 0; k < 120; ++k) {
    Vec3d wi = random_direction(rng, 89), wo = random_direction(rng, 89);
    if (k % 7 == 0) wi.z() = -wi.z();  // below the horizon: 0
    s.push_back(wi, wo, Rgb::Zero(), 1.0, true);
  }
  for_each_cook_torrance([&](auto m) {
    using M = decltype(m);
    // Where the batch loop reads Smith G1 from a row (shadowing/smith_g1_row.h, |ΔG1| < 1e-6), the
    // specular part may move by 2e-6 of itself; elsewhere the loop is eval's arithmetic.
    constexpr bool kFromRow = kG1FromRow<M::template Distribution> && M::kMaskingTerm != Masking::VGroove;
    for (const auto& set : test::model_param_sets(ModelAdapter<M>())) {
      for (int c = 0; c < 3; ++c) {
        const double* p = set.values.channel(c);
        std::vector<double> out(s.size());
        M::eval_batch(p, c, s, out.data());
        for (size_t k = 0; k < s.size(); ++k) {
          const double want = M::template eval<double>(p, c, s.wi(k), s.wo(k));
          const double lobe = s.wi(k).z() > 0 && s.wo(k).z() > 0 ? want - p[0] * kInvPi : want;
          const double tol = kFromRow ? 2e-6 * std::abs(lobe) + 1e-15 : 1e-14 * std::abs(want);
          ASSERT_NEAR(out[k], want, tol) << M::name() << " " << set.label << " pair " << k;
        }
      }
    }
  });
}

// Jets: same value as doubles, derivatives equal to a Richardson-extrapolated central difference
// to 1e-6 relative (plus 1e-12 |ρ|/|p| for round-off), for every parameter of every Cook-Torrance model.
TEST(CookTorrance, JetsMatchDoublesAndFiniteDifferences) {
  using J = ceres::Jet<double, 1>;
  std::mt19937_64 rng(14);
  std::vector<std::pair<Vec3d, Vec3d>> pairs;
  for (int k = 0; k < 20; ++k) pairs.emplace_back(random_direction(rng, 75), random_direction(rng, 75));
  double worst = 0;
  for_each_cook_torrance([&](auto m) {
    using M = decltype(m);
    for (const auto& set : test::model_param_sets(ModelAdapter<M>())) {
      const std::vector<double>& p = set.values.values[1];
      const size_t n = p.size();
      for (const auto& [wi, wo] : pairs) {
        const double f = M::template eval<double>(p.data(), 1, wi, wo);
        for (size_t i = 0; i < n; ++i) {
          std::vector<J> pj(n);
          for (size_t k = 0; k < n; ++k) pj[k] = J(p[k]);
          pj[i].v[0] = 1;
          const J v = M::template eval<J>(pj.data(), 1, wi.template cast<J>(), wo.template cast<J>());
          ASSERT_NEAR(v.a, f, 1e-13 * std::abs(f)) << M::name();
          auto at = [&](double dx) {
            std::vector<double> q = p;
            q[i] += dx;
            return M::template eval<double>(q.data(), 1, wi, wo);
          };
          // Two step sizes: a tabulated Smith Λ (Catmull-Rom, C¹) has jumps of the second
          // derivative at its nodes, and a difference whose stencil straddles one is off by
          // ~h f''; a wrong derivative fails at both steps, a straddle only at one.
          double err = INFINITY, fd = 0;
          for (double rel : {1e-4, 1e-5}) {
            const double h = rel * std::max(std::abs(p[i]), 1e-2);
            const double d = (8 * (at(h) - at(-h)) - (at(2 * h) - at(-2 * h))) / (12 * h);  // Richardson
            if (std::abs(v.v[0] - d) < err) {
              err = std::abs(v.v[0] - d);
              fd = d;
            }
          }
          // Round-off of the difference is ~1e-12 |ρ|/|p|: derivatives far below ρ/p get that floor.
          const double scale = std::abs(v.v[0]) + 1e-4 * std::abs(f) / std::max(std::abs(p[i]), 1e-2);
          worst = std::max(worst, err / scale);
          EXPECT_LE(err, 1e-6 * scale)
              << M::name() << " " << set.label << " d/d" << M::params()[i].name << " jet " << v.v[0] << " fd " << fd;
        }
      }
    }
  });
  std::printf("worst relative Jet vs finite-difference error: %.3g\n", worst);
}

// Reciprocity of every registered reciprocal model, to 1e-10 relative.
TEST(ModelCatalogue, ReciprocityOfEveryReciprocalModel) {
  for (const Model* m : all_models()) {
    if (!m->reciprocal()) continue;
    for (const auto& set : test::model_param_sets(*m)) {
      // The parameter sets hold equal values in the three channels: one channel stands for all.
      const ReciprocityCheck r = reciprocity_check(*m, set.values.channel(1), 1, 400, 99);
      EXPECT_LE(r.max_relative_error, 1e-10) << m->name() << " " << set.label;
      EXPECT_GT(r.pairs, 0) << m->name();
    }
  }
}

// Energy: with Smith masking, F ≤ 1 and kd + ks ≤ 1, albedo ≤ 1 (D normalized, G ≤ 1); the
// bound allows the quadrature's 1e-5 tolerance.
template <class M> void albedo_bounded(M) {
  const ModelAdapter<M> model;
  for (auto set : test::model_param_sets(model)) {
    for (auto& ch : set.values.values) {
      ch[0] = 0.25;                           // kd
      ch[1] = 0.75;                           // ks
      ch[size_t(M::fresnel_offset())] = 1.0;  // F0 = 1: F ≡ 1, the largest Schlick term
    }
    for (double t : {0.0, 30.0, 60.0, 80.0}) {
      const double a = albedo(model, set.values.channel(0), 0, t * kPi / 180);
      EXPECT_TRUE(std::isfinite(a)) << M::name();
      EXPECT_LE(a, 1 + 1e-4) << M::name() << " " << set.label << " theta_i " << t;
      EXPECT_GE(a, 0.25) << M::name() << " " << set.label << " theta_i " << t;  // at least the diffuse part
      std::printf("%s %s theta_i %2.0f: albedo %.6f\n", std::string(M::name()).c_str(), set.label.c_str(), t, a);
    }
  }
}

// Every distribution of ndf/distributions.h has a closed-form or tabulated Λ (shadowing/smith.h),
// cheap enough for a quadrature of the albedo.
TEST(CookTorrance, AlbedoBoundedForPlausibleParameters) {
  Distributions::for_each([]<template <class> class D>() { albedo_bounded(CookTorranceWith<D>{}); });
}


// The specular lobe alone with F = 1: its albedo at normal incidence is ∫ D G1(i)G1(o) cosθh dω
// over the reflected half vectors; for α = 0.1 nearly all microfacets are visible, so ≈ 1.
TEST(CookTorrance, SpecularAlbedoNearOneForSmoothSurfaces) {
  const double p[] = {0.0, 1.0, 0.1, 1.0};
  const ModelAdapter<CookTorranceGgx> ggx;
  const ModelAdapter<CookTorranceBeckmann> beckmann;
  const double a_ggx = albedo(ggx, p, 0, 0.0), a_beckmann = albedo(beckmann, p, 0, 0.0);
  std::printf("specular albedo at normal incidence, alpha 0.1: GGX %.6f Beckmann %.6f\n", a_ggx, a_beckmann);
  EXPECT_GT(a_beckmann, 0.98);
  EXPECT_LE(a_beckmann, 1.0 + 1e-4);
  EXPECT_GT(a_ggx, 0.95);
  EXPECT_LE(a_ggx, 1.0 + 1e-4);
}
