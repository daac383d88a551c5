// The renderer's point lights (DESIGN.md §13): a pixel adds I ρ(wi = l, wo = v) cosθl, the
// cosine belonging to the light's direction.
//  - In process, with a test-only reflector ρ = f(θi) (not reciprocal), no jitter: exact.
//  - Through `brdfkit render` with `--model lambert` (ρ constant): the cosine is cosθl, not cosθv.
//  - Through `brdfkit render` on an RGL file: measured data are asked with the view direction
//    first, data.eval(v, l) (render/reflector.h, README `render`: as Mitsuba 3 renders RGL files),
//    times cosθl.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "brdfkit/measured/rgl_tensor.h"
#include "brdfkit/render/camera.h"
#include "brdfkit/render/image_io.h"
#include "brdfkit/render/reflector.h"
#include "brdfkit/render/scene.h"
#include "brdfkit/render/sphere_renderer.h"
#include "support/test_util.h"

namespace brdfkit::test {
namespace {

// ρ(wi, wo) = 1 + 3 cos²θi, whatever wo.
class IncidenceOnlyReflector final : public render::Reflector {
 public:
  static double f(const Vec3d& wi) { return 1 + 3 * wi.z() * wi.z(); }
  Rgb eval(const Vec3d& wi, const Vec3d&) const override { return Rgb::Constant(f(wi)); }
  std::optional<Vec3d> sample(const Vec3d&, const Vec2d&, double) const override { return std::nullopt; }
  double pdf(const Vec3d&, const Vec3d&) const override { return 0.0; }
};

TEST(RenderConvention, PointLightIsRhoOfLightAndViewTimesCosLight) {
  render::Scene scene;
  scene.lights = {render::light_from_camera_angles(50, 30, Rgb::Constant(2.0))};
  render::RenderSettings st;
  st.width = st.height = 24;
  st.spp = 1;
  st.jitter = false;
  const render::RenderResult r = render::render_sphere(IncidenceOnlyReflector(), scene, st);
  const render::Camera cam(st.width, st.height, st.camera_distance);
  int checked = 0;
  double smallest_gap = 1e300;
  for (int y = 0; y < st.height; ++y)
    for (int x = 0; x < st.width; ++x) {
      const auto hit = cam.hit(x + 0.5, y + 0.5);
      if (!hit) continue;
      const Vec3d l = hit->to_local_dir(scene.lights[0].direction), v = hit->wo_local;
      if (!(l.z() > 0.05 && v.z() > 0.05) || std::abs(l.z() - v.z()) < 0.1) continue;
      const double expected = 2.0 * IncidenceOnlyReflector::f(l) * l.z();
      EXPECT_NEAR(r.radiance.at(x, y)[0], expected, 1e-12 * expected) << x << " " << y;
      // ρ(v, l) cosθl, ρ(l, v) cosθv and ρ(v, l) cosθv are all other numbers here.
      for (double wrong : {2.0 * IncidenceOnlyReflector::f(v) * l.z(), 2.0 * IncidenceOnlyReflector::f(l) * v.z(),
                           2.0 * IncidenceOnlyReflector::f(v) * v.z()})
        smallest_gap = std::min(smallest_gap, std::abs(wrong / expected - 1));
      ++checked;
    }
  EXPECT_GT(checked, 100);
  EXPECT_GT(smallest_gap, 0.05);
}

// The range of what the light adds over a pixel of a CLI render, sampled on a 5 × 5 grid of
// image points inside the pixel: a jittered pixel's mean lies in it (up to the grid's resolution,
// allowed for by a margin). `value(l, v)` is the contribution at local light and view directions;
// nullopt where it is undefined somewhere in the pixel (or the pixel is on the silhouette).
struct Range {
  double lo, hi;
  bool contains(double x, double margin) const { return x >= lo - margin * std::abs(lo) && x <= hi + margin * std::abs(hi); }
  bool disjoint(const Range& o) const { return hi < o.lo || o.hi < lo; }
};
template <class F>
std::optional<Range> range_over_pixel(const render::Camera& cam, int x, int y, const Vec3d& light_world, F value) {
  Range r{1e300, -1e300};
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) {
      const auto hit = cam.hit(x + i / 4.0, y + j / 4.0);
      if (!hit) return std::nullopt;
      const Vec3d l = hit->to_local_dir(light_world);
      if (!(l.z() > 0.1 && hit->wo_local.z() > 0.1)) return std::nullopt;
      const std::optional<double> v = value(l, hit->wo_local);
      if (!v) return std::nullopt;
      r.lo = std::min(r.lo, *v);
      r.hi = std::max(r.hi, *v);
    }
  return r;
}

// Renders `subject` (CLI arguments naming what to render) lit by one light "θ,φ,I" alone, and
// checks every pixel where the expected contribution `right` and the swapped one `wrong` are
// apart: the pixel lies in the range of `right` over the pixel, outside that of `wrong`.
template <class Right, class Wrong>
int check_cli_render(const std::string& subject, double theta, double phi, double intensity, Right right, Wrong wrong,
                     const std::string& scratch) {
  const auto dir = scratch_dir(scratch);
  const int size = 64;
  const CliResult r = run_cli("render " + subject + " --light " + std::to_string(theta) + "," + std::to_string(phi) + "," +
                              std::to_string(intensity) + " --size " + std::to_string(size) + " --spp 4 --quiet -o " +
                              (dir / "out.png").string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  if (r.exit_code != 0) return 0;
  const render::Image img = render::read_hdr_image(dir / "out.exr");
  EXPECT_EQ(img.width, size);  // one subject: the panel is its sphere alone
  EXPECT_EQ(img.height, size);
  const render::Camera cam(size, size);
  const Vec3d light = render::light_from_camera_angles(theta, phi, Rgb::Constant(1)).direction;
  int checked = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const auto good = range_over_pixel(cam, x, y, light, right), bad = range_over_pixel(cam, x, y, light, wrong);
      if (!good || !bad || !good->disjoint(*bad)) continue;
      const double got = img.at(x, y)[1];
      EXPECT_TRUE(good->contains(got, 0.01)) << subject << " pixel " << x << "," << y << ": " << got << " not in ["
                                             << good->lo << ", " << good->hi << "]";
      ++checked;
    }
  std::filesystem::remove_all(dir);
  return checked;
}

// Lambert, ρ = kd/π: I kd/π cosθl, not cosθv.
TEST(RenderConvention, CliLambertUsesCosineOfTheLight) {
  const double kd_pi = 0.6 / kPi;
  const int checked = check_cli_render(
      "--model lambert --param kd=0.6", 55, 20, 3.0,
      [&](const Vec3d& l, const Vec3d&) { return std::optional<double>(3 * kd_pi * l.z()); },
      [&](const Vec3d&, const Vec3d& v) { return std::optional<double>(3 * kd_pi * v.z()); },
      "render_convention_lambert");
  std::printf("[ convention ] render lambert: %d pixels where cos(theta_l) and cos(theta_v) tell apart\n", checked);
  EXPECT_GT(checked, 200);
}

// Measured data: I max(0, data(v, l)) cosθl (render/reflector.h), not data(l, v).
TEST(RenderConvention, CliMeasuredDataAskedWithTheViewFirst) {
  BRDFKIT_REQUIRE_DATA("rgl");
  const auto file = data_dir() / "rgl" / "cc_ibiza_sunset_rgb.bsdf";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file.string() << " is absent";
  const RglBrdf data(file);
  auto contribution = [&](const Vec3d& first, const Vec3d& second, double cos_l) -> std::optional<double> {
    const auto v = data.eval(first, second);
    if (!v) return std::nullopt;
    return 2 * std::max(0.0, (*v)[1]) * cos_l;
  };
  const int checked = check_cli_render(
      file.string() + " --proxy cosine", 40, 160, 2.0,
      [&](const Vec3d& l, const Vec3d& v) { return contribution(v, l, l.z()); },
      [&](const Vec3d& l, const Vec3d& v) { return contribution(l, v, l.z()); }, "render_convention_rgl");
  std::printf("[ convention ] render cc_ibiza_sunset: %d pixels where data(v, l) and data(l, v) tell apart\n", checked);
  EXPECT_GT(checked, 20);
}

}  // namespace
}  // namespace brdfkit::test
