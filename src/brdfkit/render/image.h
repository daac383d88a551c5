#pragma once
// A linear RGB image (radiance or an error measure per pixel) with a coverage mask: the pixels
// the sphere covers, over which image metrics average (DESIGN.md §13).
#include <cstdint>
#include <vector>

#include "brdfkit/core/vec.h"

namespace brdfkit::render {

struct Image {
  int width = 0, height = 0;
  std::vector<Rgb> pixels;              // row-major, row 0 at the top
  std::vector<std::uint8_t> covered;    // 1 where the pixel belongs to the object

  Image() = default;
  Image(int w, int h) : width(w), height(h), pixels(size_t(w) * size_t(h), Rgb::Zero()), covered(size_t(w) * size_t(h), 0) {}
  size_t size() const { return pixels.size(); }
  Rgb& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
  const Rgb& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
  size_t covered_count() const;
};

// The q-quantile (q ∈ [0, 1]) of the linear-sRGB luminance of the covered pixels; 0 when none is.
double luminance_quantile(const Image& image, double q);

// Images side by side in rows: tiles[row][col], every tile of one size (missing tiles, nullptr,
// stay black); for the comparison panel.
Image tile_images(const std::vector<std::vector<const Image*>>& tiles);

}  // namespace brdfkit::render
