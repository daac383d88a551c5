// Furnace test (DESIGN.md §13): under a constant white environment every pixel's radiance is the
// model's directional albedo at that pixel's view angle, ∫ ρ(wi, wo) cos θi dωi, for every model
// of the catalogue at its default parameters, and a Lambertian surface's ρ exactly. The reference
// is deterministic quadrature; the tolerance is 5 standard errors of the pixel (estimated by the
// renderer from its own 256 samples) plus the quadrature's error (estimated by halving its panels).
#include <gtest/gtest.h>

#include <tbb/parallel_for.h>

#include <chrono>
#include <cstdio>
#include <memory>

#include "brdfkit/measured/albedo.h"
#include "brdfkit/render/camera.h"
#include "brdfkit/render/sphere_renderer.h"

namespace brdfkit::render {
namespace {

constexpr int kSize = 16;
constexpr double kMaxViewDeg = 75;

// ∫ ρ(wi, wo) cos θi dωi for wo = R_z(φ) (sin θ, 0, cos θ), all channels, with an estimate of
// its own error: the half-vector Gauss–Legendre quadrature of measured/albedo.h (which integrates
// over its second argument, so it gets ρ with its arguments swapped, turned to azimuth φ) at 24
// and at 12 panels in s; the error estimate is their difference.
struct Reference {
  Rgb value, error;
};
Reference view_albedo(const Brdf& b, double theta, double phi) {
  const Eigen::Matrix3d r = Eigen::AngleAxisd(phi, Vec3d::UnitZ()).toRotationMatrix();
  const AlbedoIntegrand swapped = [&](const Vec3d& wi, const Vec3d& wo) { return std::optional<Rgb>(b.eval(r * wo, r * wi)); };
  AlbedoQuadrature fine, coarse;
  fine.s_panels = 24;
  coarse.s_panels = 12;
  const Rgb a = directional_albedo(swapped, theta, fine).value, c = directional_albedo(swapped, theta, coarse).value;
  return {a, (a - c).abs()};
}

// Whether ρ changes when both directions turn about n (anisotropic models need a reference per
// pixel azimuth; isotropic ones one per view angle).
bool is_anisotropic(const Model& m, const ParamValues& v) {
  const Eigen::Matrix3d r = Eigen::AngleAxisd(1.1, Vec3d::UnitZ()).toRotationMatrix();
  for (int k = 0; k < 8; ++k) {
    const Vec3d wi = spherical_direction(0.2 + 0.1 * k, 0.7 * k), wo = spherical_direction(0.9 - 0.1 * k, 2.0 + k);
    const double a = m.eval(v.channel(0), 0, wi, wo), b = m.eval(v.channel(0), 0, r * wi, r * wo);
    if (std::abs(a - b) > 1e-9 * std::max(std::abs(a), 1e-300)) return true;
  }
  return false;
}

// The albedo an isotropic model's pixel must show: linear interpolation in θ of a table every
// 2.5° (rows computed in parallel), whose interpolation error (≤ Δθ²/8 · max|a''|) is below 1e-5
// for these smooth curves.
struct AlbedoTable {
  static constexpr double kStepDeg = 2.5;
  std::vector<Reference> rows;
  explicit AlbedoTable(const Brdf& b) : rows(size_t(kMaxViewDeg / kStepDeg) + 2) {
    tbb::parallel_for(size_t(0), rows.size(), [&](size_t i) { rows[i] = view_albedo(b, double(i) * kStepDeg * kPi / 180, 0); });
  }
  Reference at(double theta) const {
    const double t = theta * 180 / kPi / kStepDeg;
    const size_t i = std::min(size_t(t), rows.size() - 2);
    const double f = t - double(i);
    return {rows[i].value + (rows[i + 1].value - rows[i].value) * f, rows[i].error.max(rows[i + 1].error) + 1e-5};
  }
};

RenderSettings furnace_settings(int spp) {
  RenderSettings s;
  s.width = s.height = kSize;
  s.spp = spp;
  s.jitter = false;
  return s;
}

Scene white_furnace() {
  Scene s;
  s.environment = EnvironmentMap::constant(Rgb::Ones());
  return s;
}

TEST(Furnace, LambertGivesRhoExactly) {
  const Model& m = model_by_name("lambert");
  ParamValues v = ParamValues::defaults(m.params());
  v.values[0][0] = 0.8, v.values[1][0] = 0.5, v.values[2][0] = 0.2;
  const RenderResult r = render_sphere(*model_reflector(Brdf(m, v)), white_furnace(), furnace_settings(256));
  double worst = 0;
  for (size_t k = 0; k < r.radiance.size(); ++k)
    if (r.radiance.covered[k]) worst = std::max(worst, (r.radiance.pixels[k] - Rgb(0.8, 0.5, 0.2)).abs().maxCoeff());
  EXPECT_LT(worst, 1e-3);
  std::printf("furnace lambert (0.8, 0.5, 0.2), 256 spp: max |pixel - rho| = %.2e over %zu pixels\n", worst,
              r.radiance.covered_count());
}

// Every covered pixel up to 75° from the view axis, all three channels.
TEST(Furnace, EveryCatalogueModelRendersItsAlbedo) {
  const Camera cam(kSize, kSize);
  for (const Model* m : all_models()) {
    const auto t0 = std::chrono::steady_clock::now();
    const ParamValues v = ParamValues::defaults(m->params());
    const RenderResult r = render_sphere(*model_reflector(Brdf(*m, v)), white_furnace(), furnace_settings(256));
    const auto t1 = std::chrono::steady_clock::now();
    const bool aniso = is_anisotropic(*m, v);
    const Brdf brdf(*m, v);
    // An isotropic model's albedo depends on θ only: tabulated once. (A pointer, not an optional:
    // GCC 12 warns of an optional holding vectors as maybe uninitialized.)
    const std::unique_ptr<const AlbedoTable> table = aniso ? nullptr : std::make_unique<const AlbedoTable>(brdf);
    double worst = 0, worst_sigmas = 0;
    int checked = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const auto hit = cam.hit(x + 0.5, y + 0.5);
        if (!hit || hit->wo_local.z() < std::cos(kMaxViewDeg * kPi / 180)) continue;
        const double theta = std::acos(hit->wo_local.z()), phi = std::atan2(hit->wo_local.y(), hit->wo_local.x());
        const Reference ref = table ? table->at(theta) : view_albedo(brdf, theta, phi);
        const Rgb& want = ref.value;
        const Rgb got = r.radiance.at(x, y), se = r.standard_error.at(x, y);
        for (int c = 0; c < 3; ++c) {
          const double err = std::abs(got[c] - want[c]), tol = 5 * se[c] + ref.error[c] + 1e-6;
          EXPECT_LE(err, tol) << m->name() << " pixel (" << x << ", " << y << ") channel " << c << ": " << got[c]
                              << " vs albedo " << want[c] << " (standard error " << se[c] << ", quadrature error " << ref.error[c] << ")";
          worst = std::max(worst, err);
          worst_sigmas = std::max(worst_sigmas, se[c] > 0 ? err / se[c] : 0.0);
          ++checked;
        }
      }
    EXPECT_GT(checked, 300) << m->name();
    const auto t2 = std::chrono::steady_clock::now();
    std::printf("furnace %-30s max |pixel - albedo| %.2e (%.1f standard errors), %d values; render %.2f s, "
                "reference %.2f s\n",
                std::string(m->name()).c_str(), worst, worst_sigmas, checked,
                std::chrono::duration<double>(t1 - t0).count(), std::chrono::duration<double>(t2 - t1).count());
  }
}

}  // namespace
}  // namespace brdfkit::render
