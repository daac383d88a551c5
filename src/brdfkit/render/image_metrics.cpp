#include "brdfkit/render/image_metrics.h"

#include <cmath>

#include "brdfkit/core/error.h"
#include "brdfkit/render/ciede2000.h"
#include "brdfkit/render/color.h"

namespace brdfkit::render {
namespace {

void check_sizes(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw InputError("image comparison", "images of different sizes (" + std::to_string(a.width) + "x" +
                                             std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                                             std::to_string(b.height) + ")");
}

// An image of a's size covering the pixels both cover, with f(a, b) there.
template <class F> Image per_pixel(const Image& a, const Image& b, F f) {
  check_sizes(a, b);
  Image out(a.width, a.height);
  for (size_t k = 0; k < a.size(); ++k)
    if (a.covered[k] && b.covered[k]) {
      out.covered[k] = 1;
      out.pixels[k] = f(a.pixels[k], b.pixels[k]);
    }
  return out;
}

}  // namespace

Image smape_image(const Image& reference, const Image& test) {
  return per_pixel(reference, test, [](const Rgb& a, const Rgb& b) {
    const Rgb den = a.abs() + b.abs();
    return Rgb((den > 0).select((a - b).abs() / den, 0.0));
  });
}

Image delta_e_image(const Image& reference, const Image& test, double white_y) {
  return per_pixel(reference, test, [&](const Rgb& a, const Rgb& b) {
    return Rgb::Constant(ciede2000(linear_srgb_to_lab(a, white_y), linear_srgb_to_lab(b, white_y)));
  });
}

double reference_white(const Image& reference) {
  const double y = luminance_quantile(reference, 0.99);
  return y > 0 ? y : 1;
}

double covered_mean(const Image& image) {
  double sum = 0;
  size_t n = 0;
  for (size_t k = 0; k < image.size(); ++k)
    if (image.covered[k]) sum += image.pixels[k].mean(), ++n;
  return n ? sum / double(n) : 0;
}

ImageErrors compare_images(const Image& reference, const Image& test, double white_y) {
  ImageErrors e;
  e.white_y = white_y;
  const Image sq = per_pixel(reference, test, [](const Rgb& a, const Rgb& b) { return Rgb((a - b).square()); });
  e.pixels = sq.covered_count();
  e.rmse = std::sqrt(covered_mean(sq));
  e.mean_smape = covered_mean(smape_image(reference, test));
  e.mean_delta_e = covered_mean(delta_e_image(reference, test, white_y));
  return e;
}

}  // namespace brdfkit::render
