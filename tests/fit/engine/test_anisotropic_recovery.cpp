// Anisotropic recovery: scattered samples of an anisotropic Cook-Torrance lobe whose tangent is
// turned from the frame's x axis, at several incidence azimuths, are fitted back to 1e-3 with the
// orientation found by the fit (the start scan covers phi_t's box) or given (a one-point box); a
// fit may return the same lobe with its widths swapped and its tangent turned by π/2.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "brdfkit/fit/procedure/procedure.h"
#include "brdfkit/measured/rgl_tensor.h"
#include "brdfkit/measured/rgl_writer.h"
#include "support/fit_test_util.h"
#include "support/test_util.h"

namespace brdfkit::fit {
namespace {

using test::make_values;

constexpr double kDeg = kPi / 180;

// θi = 10°…80° at φi = 0°, 60°, 120°; outgoing rings 1 − cos θo = (k/10)², k = 0…9, 36 azimuths
// each over the whole circle; a sample's weight is its ring's band of solid angle / its count /
// the three azimuths of its θi, so the samples of one θi hold 2π (fit/metric/metric_samples.h).
test::ScatteredData anisotropic_samples(const Model& model, const ParamValues& values) {
  SampleSet s;
  const Brdf brdf(model, values);
  auto edge = [](int k) { return k <= 0 ? 0.0 : k >= 10 ? 1.0 : std::pow((k - 0.5) / 10, 2); };
  for (int i = 1; i <= 8; ++i)
    for (double phi_i : {0.0, 60 * kDeg, 120 * kDeg})
      for (int k = 0; k < 10; ++k) {
        const double theta_o = std::acos(1 - std::pow(k / 10.0, 2));
        const int n = k == 0 ? 1 : 36;
        for (int j = 0; j < n; ++j) {
          const Vec3d wi = spherical_direction(i * 10 * kDeg, phi_i),
                      wo = spherical_direction(theta_o, 2 * kPi * j / n);
          s.push_back(wi, wo, brdf.eval(wi, wo), 2 * kPi * (edge(k + 1) - edge(k)) / n / 3, true);
        }
      }
  return test::ScatteredData(std::move(s), "synthetic-anisotropic");
}

// The same lobe written with φ modulo π, and for two widths as (αx, αy, φ) = (αy, αx, φ + π/2)
// (models/cook_torrance_anisotropic.h): the form of `got` whose widths are in `want`'s order.
ParamValues same_lobe_as(const Model& m, const ParamValues& want, ParamValues got) {
  const int ax_index = find_param(m.params(), "alpha_x");
  const size_t ax = size_t(ax_index), ay = ax + 1, phi = size_t(find_param(m.params(), "phi_t"));
  for (int c = 0; c < 3; ++c) {
    auto& g = got.values[size_t(c)];
    if (ax_index >= 0 && (g[ax] < g[ay]) != (want.values[size_t(c)][ax] < want.values[size_t(c)][ay])) {
      std::swap(g[ax], g[ay]);
      g[phi] += kPi / 2;
    }
    g[phi] -= kPi * std::round((g[phi] - want.values[size_t(c)][phi]) / kPi);
  }
  return got;
}

void expect_recovered(const Model& m, const ParamValues& want, const ParamValues& fitted) {
  const ParamValues got = same_lobe_as(m, want, fitted);
  for (size_t i = 0; i < m.params().size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double x = want.values[size_t(c)][i], y = got.values[size_t(c)][i];
      EXPECT_NEAR(y, x, 1e-3 * std::abs(x)) << m.name() << " " << m.params()[i].name << "[" << c << "]";
    }
}

ParamValues truth(const Model& m, double ax, double ay, double phi_t) {
  return make_values(m, {{"kd", Rgb(0.2, 0.15, 0.1)},
                         {"ks", Rgb(0.8, 0.6, 0.5)},
                         {"alpha_x", Rgb::Constant(ax)},
                         {"alpha_y", Rgb::Constant(ay)},
                         {"phi_t", Rgb::Constant(phi_t)},
                         {"F0", Rgb(0.3, 0.4, 0.5)}});
}

TEST(AnisotropicRecovery, TurnedLobesAreFittedBackWithTheirOrientation) {
  for (const auto& [name, ax, ay, phi] : {std::tuple{"cook-torrance-ggx-aniso", 0.12, 0.35, 0.5},
                                          std::tuple{"cook-torrance-beckmann-aniso", 0.3, 0.1, -1.1}}) {
    const Model& m = model_by_name(name);
    const ParamValues want = truth(m, ax, ay, phi);
    const test::ScatteredData data = anisotropic_samples(m, want);
    const ProcedureResult r = run_procedure(m, data, FitSettings{});
    expect_recovered(m, want, r.fit.values);
    std::printf("%s: %d iterations, ngan %.3g\n", name, r.fit.iterations, r.fit.metric_value);
  }
}

// The same lobe written as an anisotropic RGL file (9 θi × 13 φi over the half circle its half-turn
// symmetry lets the file store, 32² nodes each) and read back: metrics integrate anisotropic data
// over the file's own nodes, every incidence azimuth and its half-turned image (fit/metric/
// metric.cpp), where the file holds the source's values, so the fit recovers the truth.
TEST(AnisotropicRecovery, AnAnisotropicRglFileIsFittedBack) {
  const Model& m = model_by_name("cook-torrance-ggx-aniso");
  const ParamValues want = truth(m, 0.2, 0.4, 0.5);
  const Brdf brdf(m, want);
  const auto dir = test::scratch_dir("anisotropic_rgl_recovery");
  write_rgl(dir / "ggx.bsdf", [&](const Vec3d& wi, const Vec3d& wo) { return std::optional<Rgb>(brdf.eval(wi, wo)); },
            {.theta_i = 9, .phi_i = 13, .symmetry = 2, .grid = 32, .ndf_nodes = 48, .ndf_azimuths = 48, .vndf_nodes = 64});
  const RglBrdf data(dir / "ggx.bsdf");
  const ProcedureResult r = run_procedure(m, data, FitSettings{});
  expect_recovered(m, want, r.fit.values);
  std::printf("anisotropic RGL file: %d iterations, ngan %.3g\n", r.fit.iterations, r.fit.metric_value);
  std::filesystem::remove_all(dir);
}

// Poulin-Fournier's cylinders (gap, height, Phong exponent and axis) from the same layout.
TEST(AnisotropicRecovery, PoulinFournierCylindersAreFittedBack) {
  const Model& m = model_by_name("poulin-fournier");
  const ParamValues want = make_values(m, {{"kd", Rgb(0.2, 0.15, 0.1)},
                                           {"ks", Rgb(0.8, 0.6, 0.5)},
                                           {"n", Rgb::Constant(40)},
                                           {"d", Rgb::Constant(0.3)},
                                           {"h", Rgb::Constant(0.6)},
                                           {"phi_t", Rgb::Constant(0.4)}});
  const test::ScatteredData data = anisotropic_samples(m, want);
  const ProcedureResult r = run_procedure(m, data, FitSettings{});
  expect_recovered(m, want, r.fit.values);
  std::printf("poulin-fournier: %d iterations, ngan %.3g\n", r.fit.iterations, r.fit.metric_value);
}

TEST(AnisotropicRecovery, AGivenOrientationIsHeldAndTheRestFitted) {
  const Model& m = model_by_name("cook-torrance-ggx-aniso");
  const ParamValues want = truth(m, 0.2, 0.07, 1.0);
  const test::ScatteredData data = anisotropic_samples(m, want);
  const ProcedureResult r = run_procedure(m, data, FitSettings{.bounds = {{"phi_t", {1.0, 1.0}}}});
  expect_recovered(m, want, r.fit.values);
  // A wrong given orientation cannot reach the truth.
  const ProcedureResult wrong = run_procedure(m, data, FitSettings{.bounds = {{"phi_t", {0.8, 0.8}}}});
  EXPECT_GT(wrong.fit.metric_value, 100 * r.fit.metric_value + 1e-6);
}

}  // namespace
}  // namespace brdfkit::fit
