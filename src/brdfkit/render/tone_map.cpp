#include "brdfkit/render/tone_map.h"

#include <algorithm>
#include <cmath>

#include "brdfkit/render/color.h"

namespace brdfkit::render {
namespace {

unsigned char to_byte(double encoded) { return static_cast<unsigned char>(std::lround(std::clamp(encoded, 0.0, 1.0) * 255)); }

}  // namespace

double auto_exposure(const Image& image) {
  const double y = luminance_quantile(image, 0.99);
  return y > 0 ? std::log2(0.9 / y) : 0;
}

Rgb8Image tone_map(const Image& image, double exposure, const Rgb& background) {
  Rgb8Image out{image.width, image.height, std::vector<unsigned char>(image.size() * 3)};
  const double scale = std::exp2(exposure);
  for (size_t k = 0; k < image.size(); ++k) {
    const Rgb v = image.covered[k] ? Rgb(image.pixels[k] * scale) : background;
    for (int c = 0; c < 3; ++c) out.rgb[3 * k + size_t(c)] = to_byte(srgb_encode(v[c]));
  }
  return out;
}

Rgb cubehelix(double t) {
  // Green 2011 Eq. 2 with s = 0.5, r = −1.5, h = 1, γ = 1.
  t = std::clamp(t, 0.0, 1.0);
  const double phi = 2 * kPi * (0.5 / 3 + -1.5 * t), amp = t * (1 - t) / 2;
  const double c = std::cos(phi), s = std::sin(phi);
  const Rgb v(t + amp * (-0.14861 * c + 1.78277 * s), t + amp * (-0.29227 * c - 0.90649 * s), t + amp * (1.97294 * c));
  return v.cwiseMax(0.0).cwiseMin(1.0);
}

Rgb8Image false_color(const Image& scalar, double vmax) {
  Rgb8Image out{scalar.width, scalar.height, std::vector<unsigned char>(scalar.size() * 3, 0)};
  for (size_t k = 0; k < scalar.size(); ++k) {
    if (!scalar.covered[k]) continue;
    // Green's map is defined on display values; it is written as they are, not sRGB-encoded.
    const Rgb v = cubehelix(vmax > 0 ? scalar.pixels[k].mean() / vmax : 0);
    for (int c = 0; c < 3; ++c) out.rgb[3 * k + size_t(c)] = to_byte(v[c]);
  }
  return out;
}

}  // namespace brdfkit::render
