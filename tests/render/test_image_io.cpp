// Image files round-trip through their libraries: linear EXR to float precision, PNG to the byte,
// PNG text chunks written; tone mapping follows IEC 61966-2-1; sMAPE of seed 004 Eq. 30 on known
// pixels; bad files are refused with the file's name.
#include <gtest/gtest.h>

#include <fstream>

#include "brdfkit/core/error.h"
#include "brdfkit/render/color.h"
#include "brdfkit/render/image_io.h"
#include "brdfkit/render/image_metrics.h"
#include "brdfkit/render/tone_map.h"
#include "support/test_util.h"

namespace brdfkit::render {
namespace {

Image gradient(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      img.at(x, y) = Rgb(0.01 * x, 0.5 + 0.1 * y, 123.456 / (1 + x + y));
      img.covered[size_t(y) * size_t(w) + size_t(x)] = 1;
    }
  return img;
}

TEST(ImageIo, ExrRoundTripsInFloat) {
  const auto dir = test::scratch_dir("exr");
  const Image img = gradient(7, 5);
  write_exr(dir / "a.exr", img);
  const Image back = read_hdr_image(dir / "a.exr");
  ASSERT_EQ(back.width, 7);
  ASSERT_EQ(back.height, 5);
  for (size_t k = 0; k < img.size(); ++k)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(back.pixels[k][c], double(float(img.pixels[k][c])));
  std::filesystem::remove_all(dir);
}

TEST(ImageIo, PngRoundTripsAndToneMapIsSrgb) {
  const auto dir = test::scratch_dir("png");
  Image img(3, 1);
  img.pixels = {Rgb(0.0, 0.0031308, 0.5), Rgb(1.0, 0.25, 2.0), Rgb(0.18, 0.18, 0.18)};
  img.covered = {1, 1, 1};
  const Rgb8Image t = tone_map(img, 0.0);
  // IEC 61966-2-1: 0.0031308 → 12.92 · 0.0031308 = 0.04045; 0.5 → 1.055 · 0.5^(1/2.4) − 0.055 = 0.7354.
  EXPECT_EQ(t.rgb[1], 10);   // round(0.04045 · 255)
  EXPECT_EQ(t.rgb[2], 188);  // round(0.7354 · 255)
  EXPECT_EQ(t.rgb[5], 255);  // 2.0 clamps
  EXPECT_EQ(tone_map(img, 1.0).rgb[8], 162);  // one stop up: 0.36 → 1.055 · 0.36^(1/2.4) − 0.055 = 0.6342
  write_png(dir / "a.png", t, {{"exposure", "0 EV"}});
  const Rgb8Image back = read_png(dir / "a.png");
  EXPECT_EQ(back.rgb, t.rgb);
  std::ifstream in(dir / "a.png", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // The whole tEXt chunk: length 13, type, keyword "exposure", NUL, the text.
  const std::string chunk("\0\0\0\x0dtEXtexposure\0" "0 EV", 21);
  EXPECT_NE(bytes.find(chunk), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(ImageIo, BadFilesNameTheFile) {
  const auto dir = test::scratch_dir("bad_image");
  std::ofstream(dir / "x.exr") << "not an exr";
  try {
    read_hdr_image(dir / "x.exr");
    FAIL() << "accepted a bad EXR";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("x.exr"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_hdr_image(dir / "missing.exr"), InputError);
  EXPECT_THROW(read_hdr_image(dir / "x.png"), InputError);
  std::filesystem::remove_all(dir);
}

TEST(ImageMetrics, SmapeRmseAndDeltaEOnKnownPixels) {
  Image a(2, 1), b(2, 1);
  a.pixels = {Rgb(1, 2, 0), Rgb(0.5, 0.5, 0.5)};
  b.pixels = {Rgb(3, 2, 0), Rgb(0.5, 0.5, 0.5)};
  a.covered = b.covered = {1, 1};
  const Image s = smape_image(a, b);
  EXPECT_DOUBLE_EQ(s.pixels[0][0], 0.5);  // |1 − 3| / (1 + 3)
  EXPECT_DOUBLE_EQ(s.pixels[0][1], 0.0);
  EXPECT_DOUBLE_EQ(s.pixels[0][2], 0.0);  // 0/0 → 0
  const ImageErrors e = compare_images(a, b, 1.0);
  EXPECT_DOUBLE_EQ(e.rmse, std::sqrt(4.0 / 6));
  EXPECT_DOUBLE_EQ(e.mean_smape, 0.5 / 6);
  EXPECT_EQ(e.pixels, 2u);
  EXPECT_GT(e.mean_delta_e, 0);
  EXPECT_EQ(delta_e_image(a, b, 1.0).pixels[1][0], 0.0);
}

}  // namespace
}  // namespace brdfkit::render
