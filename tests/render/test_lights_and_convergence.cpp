// Point lights are exact (no Monte Carlo): every pixel equals I ρ(l, wo) cos θl; environment
// lighting converges as 1/√N (error against a 16384-spp reference at N = 16, 64, 256); the
// environment map's sampling density integrates to 1 and matches where its samples land.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "brdfkit/measured/summary.h"
#include "brdfkit/render/camera.h"
#include "brdfkit/render/sphere_renderer.h"
#include "render_test_scenes.h"

namespace brdfkit::render {
namespace {

Brdf ggx(double kd, double alpha) {
  const Model& m = model_by_name("cook-torrance-ggx");
  ParamValues v = ParamValues::defaults(m.params());
  v.set(m.params(), "kd", kd);
  v.set(m.params(), "alpha", alpha);
  return Brdf(m, v);
}

TEST(PointLight, EqualsRhoCosineTimesIntensity) {
  const Brdf b = ggx(0.3, 0.25);
  Scene scene;
  scene.lights = {light_from_camera_angles(35, 60, Rgb(2.5, 2.0, 1.5)), light_from_camera_angles(70, -150, Rgb(0.5, 0.5, 0.5))};
  RenderSettings st = test::small_settings(32, 3);
  st.jitter = false;
  const RenderResult r = render_sphere(*model_reflector(b), scene, st);
  const Camera cam(32, 32);
  double worst = 0;
  size_t lit = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const auto hit = cam.hit(x + 0.5, y + 0.5);
      ASSERT_EQ(bool(hit), bool(r.radiance.covered[size_t(y) * 32 + size_t(x)]));
      if (!hit) continue;
      Rgb want = Rgb::Zero();
      for (const PointLight& l : scene.lights) {
        const Vec3d wi = hit->to_local_dir(l.direction);
        if (wi.z() > 0) want += l.intensity * b.eval(wi, hit->wo_local) * wi.z();
      }
      const Rgb got = r.radiance.at(x, y);
      const double err = ((got - want).abs() / want.abs().max(1e-12)).maxCoeff();
      EXPECT_LE(err, 1e-6) << "pixel " << x << ", " << y;
      EXPECT_EQ(r.standard_error.at(x, y).maxCoeff(), 0.0);
      worst = std::max(worst, err);
      lit += want.maxCoeff() > 0;
    }
  EXPECT_GT(lit, 400u);
  std::printf("point lights: %zu lit pixels, max relative |pixel - I rho cos| = %.2e\n", lit, worst);
}

// A light straight from the camera on a Lambertian sphere: ρ cos θ = kd/π · n·z, the textbook
// shading, which pins down the frame and the camera geometry independently of the renderer's code.
TEST(PointLight, HeadlightOnLambertIsCosineShading) {
  const Model& m = model_by_name("lambert");
  ParamValues v = ParamValues::defaults(m.params());
  v.set(m.params(), "kd", 0.6);
  Scene scene;
  scene.lights = {light_from_camera_angles(0, 0, Rgb::Ones())};
  RenderSettings st = test::small_settings(33, 1);
  st.jitter = false;
  const RenderResult r = render_sphere(*model_reflector(Brdf(m, v)), scene, st);
  EXPECT_NEAR(r.radiance.at(16, 16)[0], 0.6 / kPi, 1e-12);  // the centre pixel faces the camera
  // Pixel centres at offset s from the centre see the sphere point whose normal's z is the cosine.
  const Camera cam(33, 33);
  const auto hit = cam.hit(26.5, 16.5);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(r.radiance.at(26, 16)[0], 0.6 / kPi * hit->to_world(Vec3d::UnitZ()).z(), 1e-12);
  EXPECT_LT(hit->to_world(Vec3d::UnitZ()).z(), 0.9);
}

double rmse(const Image& a, const Image& b) {
  double s = 0;
  size_t n = 0;
  for (size_t k = 0; k < a.size(); ++k)
    if (a.covered[k] && b.covered[k]) s += (a.pixels[k] - b.pixels[k]).square().sum(), n += 3;
  return std::sqrt(s / double(n));
}

TEST(Convergence, ErrorFallsAsOneOverRootN) {
  const Brdf b = ggx(0.3, 0.2);
  const Scene scene = test::sky_scene();
  auto settings = [](int spp, std::uint64_t seed) {
    RenderSettings s = test::small_settings(16, spp, seed);
    s.jitter = false;  // pixel-footprint noise would not fall with N below the reference's
    return s;
  };
  const Image reference = render_sphere(*model_reflector(b), scene, settings(16384, 99)).radiance;
  const int counts[3] = {16, 64, 256};
  double err[3];
  for (int i = 0; i < 3; ++i) {
    // The mean over 8 seeds of the squared error, so one lucky image does not decide the slope.
    double sq = 0;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) sq += std::pow(rmse(render_sphere(*model_reflector(b), scene, settings(counts[i], seed)).radiance, reference), 2);
    err[i] = std::sqrt(sq / 8);
  }
  const double slope = std::log(err[2] / err[0]) / std::log(256.0 / 16.0);
  std::printf("convergence: RMSE %.4g (16 spp), %.4g (64), %.4g (256); ratios %.2f, %.2f (1/sqrt N: 2); slope %.3f\n",
              err[0], err[1], err[2], err[0] / err[1], err[1] / err[2], slope);
  EXPECT_NEAR(slope, -0.5, 0.07);
  EXPECT_NEAR(err[0] / err[1], 2.0, 0.35);
  EXPECT_NEAR(err[1] / err[2], 2.0, 0.35);
}

TEST(EnvironmentSampling, DensityIntegratesToOneAndMatchesSamples) {
  // Turned by 45° = 8 map pixels, so a midpoint rule whose cells nest in the map's pixels
  // integrates the piecewise-constant density exactly (up to rounding).
  const EnvironmentMap env(test::synthetic_sky(), 45, 1);
  double integral = 0;
  const int nt = 32 * 8, np = 64 * 8;
  for (int i = 0; i < nt; ++i)
    for (int j = 0; j < np; ++j) {
      const double t = kPi * (i + 0.5) / nt, p = 2 * kPi * (j + 0.5) / np;
      integral += env.pdf(Vec3d(std::sin(t) * std::cos(p), std::cos(t), std::sin(t) * std::sin(p))) * std::sin(t) *
                  (kPi / nt) * (2 * kPi / np);
    }
  EXPECT_NEAR(integral, 1.0, 1e-6);  // p(u, v) is stored in float
  // Every sample's reported density is pdf() at that direction, and the samples estimate
  // ∫ L dω without bias (the sampled direction reads the pixel its density was built from).
  double direct = 0;
  for (int i = 0; i < nt; ++i)
    for (int j = 0; j < np; ++j) {
      const double t = kPi * (i + 0.5) / nt, p = 2 * kPi * (j + 0.5) / np;
      direct += luminance(env.radiance(Vec3d(std::sin(t) * std::cos(p), std::cos(t), std::sin(t) * std::sin(p)))) *
                std::sin(t) * (kPi / nt) * (2 * kPi / np);
    }
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  double estimate = 0;
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    double p = 0;
    const Vec3d d = env.sample(Vec2d(u(rng), u(rng)), &p);
    EXPECT_NEAR(d.norm(), 1.0, 1e-12);
    EXPECT_NEAR(p, env.pdf(d), 1e-6 * p);  // the map stores p(u, v) in float
    estimate += luminance(env.radiance(d)) / p / n;
  }
  EXPECT_NEAR(estimate, direct, 0.01 * direct);
  std::printf("environment map: pdf integrates to %.9f; int L dw = %.5f, by sampling %.5f\n", integral, direct, estimate);
}

}  // namespace
}  // namespace brdfkit::render
