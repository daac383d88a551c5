#pragma once
// Image files through libraries, never hand-written codecs: OpenEXR (linear float RGB, read and
// written), Radiance RGBE .hdr (read, stb_image) and 8-bit sRGB PNG (written, libpng). Writers are
// atomic (a temporary in the same folder renamed into place). Bad input: InputError naming the file.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "brdfkit/render/image.h"

namespace brdfkit::render {

// An .exr or .hdr file as linear RGB (every pixel covered). A one-channel (Y) EXR gives grey.
Image read_hdr_image(const std::filesystem::path& file);

// Linear RGB as 32-bit float OpenEXR (ZIP compression).
void write_exr(const std::filesystem::path& file, const Image& image);

// 8-bit RGB pixels, row-major from the top, already encoded.
struct Rgb8Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
};
// PNG with text chunks (e.g. "exposure" → "-1.5 EV"): what a viewer needs to read the image.
void write_png(const std::filesystem::path& file, const Rgb8Image& image, const std::map<std::string, std::string>& text = {});
// Reads an 8-bit RGB(A) PNG back (tests and the report's checks); InputError when it is not one.
Rgb8Image read_png(const std::filesystem::path& file);

}  // namespace brdfkit::render
