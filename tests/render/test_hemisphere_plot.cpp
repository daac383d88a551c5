// The parabolic map of render/hemisphere_plot.h: each pixel shows the direction the map puts there,
// and an anisotropic distribution drawn on it keeps its orientation and widths.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "brdfkit/core/turned_frame.h"
#include "brdfkit/ndf/ggx_anisotropic.h"
#include "brdfkit/render/hemisphere_plot.h"
#include "support/test_util.h"

namespace brdfkit::render {
namespace {

// Heidrich & Seidel 1998: a direction w lands at (w_x, w_y)/(1 + w_z); the normal at the centre,
// the horizon on the unit circle.
TEST(ParabolicMap, DirectionsLandWhereTheMapPutsThem) {
  for (double u : {-0.9, -0.3, 0.0, 0.4, 0.7})
    for (double v : {-0.6, 0.0, 0.2, 0.5}) {
      if (u * u + v * v > 1) continue;
      const Vec3d w = parabolic_direction(u, v);
      EXPECT_NEAR(w.norm(), 1.0, 1e-15);
      EXPECT_NEAR(w.x() / (1 + w.z()), u, 1e-15);
      EXPECT_NEAR(w.y() / (1 + w.z()), v, 1e-15);
    }
  EXPECT_NEAR(parabolic_direction(1, 0).z(), 0.0, 1e-15);
  EXPECT_NEAR(parabolic_direction(0, 0).z(), 1.0, 1e-15);
}

// GGX with αx = 0.1 along a tangent at 30°, αy = 0.3: along a principal axis of width α,
// D/D(0) = 1/(cos⁴θ (1 + tan²θ/α²)²) falls to 1/100 where (1 + t²/α²)/(1 + t²) = 10, t = tanθ:
// t² = 9/(1/α² − 10), so at θ = 17.5° along the tangent and 70.6° across it, i.e. at
// tan(θ/2) × 100 = 15.4 and 70.8 pixels from the centre of a 201-pixel map. A mirrored or
// transposed map would swap the two probes.
TEST(ParabolicMap, AnisotropicDistributionKeepsItsShape) {
  const double widths[2] = {0.1, 0.3};
  const GgxAnisotropic<double> ggx(widths);
  const TurnedFrame<double> lobe(kPi / 6);
  const int size = 201;
  const Image map = parabolic_map([&](const Vec3d& h) { return h.z() > 0 ? ggx.D(lobe.to_local(h)) : 0.0; }, size);
  const double peak = map.at(100, 100).x();
  // Walk from the centre along a direction in the image until D falls below 1 % of the peak.
  auto reach = [&](double angle) {
    for (int r = 1; r < 100; ++r) {
      const int x = 100 + int(std::lround(r * std::cos(angle))), y = 100 - int(std::lround(r * std::sin(angle)));
      if (map.at(x, y).x() < 0.01 * peak) return r;
    }
    return 100;
  };
  const int along = reach(kPi / 6), across = reach(kPi / 6 + kPi / 2);
  std::printf("parabolic map of GGX (0.1, 0.3) at 30 deg: 1 %% level at %d px along the tangent, %d px across\n", along,
              across);
  auto pixels = [](double alpha) { return 100 * std::tan(0.5 * std::atan(std::sqrt(9 / (1 / (alpha * alpha) - 10)))); };
  EXPECT_NEAR(along, pixels(0.1), 1.5);
  EXPECT_NEAR(across, pixels(0.3), 1.5);
  // Written and read back as the CLI writes it.
  const auto dir = test::scratch_dir("hemisphere_plot");
  write_png(dir / "ggx.png", log_false_color(map, 4));
  const Rgb8Image back = read_png(dir / "ggx.png");
  ASSERT_EQ(back.width, size);
  EXPECT_EQ(back.rgb[(size_t(100) * size + 100) * 3], 255);  // the peak is white
  EXPECT_EQ(back.rgb[0], 0);                                  // the corner lies outside the disk
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace brdfkit::render
