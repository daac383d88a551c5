#include "brdfkit/render/hemisphere_plot.h"

#include <algorithm>
#include <cmath>

#include "brdfkit/render/tone_map.h"

namespace brdfkit::render {

Vec3d parabolic_direction(double u, double v) {
  const double r2 = u * u + v * v;
  return Vec3d(2 * u, 2 * v, 1 - r2) / (1 + r2);
}

Image parabolic_map(const std::function<double(const Vec3d&)>& f, int size) {
  Image out(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double u = 2 * (x + 0.5) / size - 1, v = 1 - 2 * (y + 0.5) / size;  // row 0 at the top
      if (u * u + v * v > 1) continue;
      out.at(x, y) = Rgb::Constant(f(parabolic_direction(u, v)));
      out.covered[size_t(y) * size_t(size) + size_t(x)] = 1;
    }
  return out;
}

Rgb8Image log_false_color(const Image& values, double decades) {
  double top = 0;
  for (size_t k = 0; k < values.size(); ++k)
    if (values.covered[k]) top = std::max(top, values.pixels[k].mean());
  Image scaled = values;
  for (size_t k = 0; k < values.size(); ++k) {
    const double x = values.pixels[k].mean();
    const double t = top > 0 && x > 0 ? 1 + std::log10(x / top) / decades : 0;
    scaled.pixels[k] = Rgb::Constant(std::clamp(t, 0.0, 1.0));
  }
  return false_color(scaled, 1.0);
}

}  // namespace brdfkit::render
