#include "brdfkit/render/image.h"

#include <algorithm>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/summary.h"

namespace brdfkit::render {

size_t Image::covered_count() const { return size_t(std::count(covered.begin(), covered.end(), std::uint8_t(1))); }

double luminance_quantile(const Image& image, double q) {
  std::vector<double> y;
  for (size_t k = 0; k < image.size(); ++k)
    if (image.covered[k]) y.push_back(luminance(image.pixels[k]));
  if (y.empty()) return 0;
  const size_t at = std::min(y.size() - 1, size_t(q * double(y.size())));
  std::nth_element(y.begin(), y.begin() + std::ptrdiff_t(at), y.end());
  return y[at];
}

Image tile_images(const std::vector<std::vector<const Image*>>& tiles) {
  int w = 0, h = 0;
  size_t cols = 0;
  for (const auto& row : tiles) {
    cols = std::max(cols, row.size());
    for (const Image* t : row)
      if (t) w = t->width, h = t->height;
  }
  Image out(w * int(cols), h * int(tiles.size()));
  for (size_t r = 0; r < tiles.size(); ++r)
    for (size_t c = 0; c < tiles[r].size(); ++c) {
      const Image* t = tiles[r][c];
      if (!t) continue;
      if (t->width != w || t->height != h) throw InputError("panel", "tiles of different sizes");
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const int ox = int(c) * w + x, oy = int(r) * h + y;
          out.at(ox, oy) = t->at(x, y);
          out.covered[size_t(oy) * size_t(out.width) + size_t(ox)] = t->covered[size_t(y) * size_t(w) + size_t(x)];
        }
    }
  return out;
}

}  // namespace brdfkit::render
