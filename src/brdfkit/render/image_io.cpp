#include "brdfkit/render/image_io.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <png.h>
#include <stb_image.h>

#include <csetjmp>
#include <cstdio>
#include <memory>

#include "brdfkit/core/atomic_file.h"
#include "brdfkit/core/error.h"

namespace brdfkit::render {
namespace {

namespace fs = std::filesystem;

Image read_exr(const fs::path& file) {
  try {
    Imf::InputFile in(file.c_str());
    const Imath::Box2i dw = in.header().dataWindow();
    const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
    const Imf::ChannelList& ch = in.header().channels();
    const bool rgb = ch.findChannel("R") && ch.findChannel("G") && ch.findChannel("B");
    if (!rgb && !ch.findChannel("Y")) throw InputError(file.string(), "an EXR without R, G, B or Y channels");
    std::vector<float> data(size_t(w) * size_t(h) * 3, 0.0f);
    Imf::FrameBuffer fb;
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < (rgb ? 3 : 1); ++c) {
      // Slices are addressed from the data window's origin, hence the offset base pointer.
      char* base = reinterpret_cast<char*>(data.data() + c) -
                   (ptrdiff_t(dw.min.x) + ptrdiff_t(dw.min.y) * w) * ptrdiff_t(3 * sizeof(float));
      fb.insert(rgb ? names[c] : "Y", Imf::Slice(Imf::FLOAT, base, 3 * sizeof(float), size_t(w) * 3 * sizeof(float)));
    }
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    Image img(w, h);
    for (size_t k = 0; k < img.size(); ++k) {
      const float* p = &data[3 * k];
      img.pixels[k] = rgb ? Rgb(p[0], p[1], p[2]) : Rgb(p[0], p[0], p[0]);
      img.covered[k] = 1;
    }
    return img;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(file.string(), std::string("not a readable OpenEXR file: ") + e.what());
  }
}

Image read_rgbe(const fs::path& file) {
  if (!stbi_is_hdr(file.c_str())) throw InputError(file.string(), "not a Radiance RGBE (.hdr) file");
  int w = 0, h = 0, n = 0;
  std::unique_ptr<float, void (*)(void*)> data(stbi_loadf(file.c_str(), &w, &h, &n, 3), stbi_image_free);
  if (!data) throw InputError(file.string(), std::string("unreadable .hdr file: ") + stbi_failure_reason());
  Image img(w, h);
  for (size_t k = 0; k < img.size(); ++k) {
    img.pixels[k] = Rgb(data.get()[3 * k], data.get()[3 * k + 1], data.get()[3 * k + 2]);
    img.covered[k] = 1;
  }
  return img;
}

void png_to_string(png_structp png, png_bytep data, png_size_t n) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), n);
}

}  // namespace

Image read_hdr_image(const fs::path& file) {
  if (!fs::is_regular_file(file)) throw InputError(file.string(), "no such file");
  const std::string ext = file.extension().string();
  if (ext == ".exr" || ext == ".EXR") return read_exr(file);
  if (ext == ".hdr" || ext == ".HDR" || ext == ".pic") return read_rgbe(file);
  throw InputError(file.string(), "an environment map must be OpenEXR (.exr) or Radiance RGBE (.hdr)");
}

void write_exr(const fs::path& file, const Image& image) {
  std::vector<float> data(image.size() * 3);
  for (size_t k = 0; k < image.size(); ++k)
    for (int c = 0; c < 3; ++c) data[3 * k + size_t(c)] = float(image.pixels[k][c]);
  Imf::Header header(image.width, image.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  Imf::FrameBuffer fb;
  const char* names[3] = {"R", "G", "B"};
  for (int c = 0; c < 3; ++c) {
    header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
    fb.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(data.data() + c), 3 * sizeof(float),
                                   size_t(image.width) * 3 * sizeof(float)));
  }
  Imf::StdOSStream os;
  {
    Imf::OutputFile out(os, header);
    out.setFrameBuffer(fb);
    out.writePixels(image.height);
  }
  write_file_atomically(file, os.str());
}

void write_png(const fs::path& file, const Rgb8Image& image, const std::map<std::string, std::string>& text) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) throw std::runtime_error("libpng: out of memory");
  std::string bytes;
  // Built before setjmp: libpng's error path longjmps back here past no constructor.
  std::vector<png_text> chunks;
  for (const auto& [key, value] : text) {
    png_text t{};
    t.compression = PNG_TEXT_COMPRESSION_NONE;
    t.key = const_cast<char*>(key.c_str());
    t.text = const_cast<char*>(value.c_str());
    chunks.push_back(t);
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("libpng failed writing " + file.string());
  }
  png_set_write_fn(png, &bytes, png_to_string, nullptr);
  png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  if (!chunks.empty()) png_set_text(png, info, chunks.data(), int(chunks.size()));
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y)
    png_write_row(png, const_cast<png_bytep>(&image.rgb[size_t(y) * size_t(image.width) * 3]));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  write_file_atomically(file, bytes);
}

Rgb8Image read_png(const fs::path& file) {
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&img, file.c_str())) throw InputError(file.string(), "not a readable PNG file");
  img.format = PNG_FORMAT_RGB;
  Rgb8Image out{int(img.width), int(img.height), std::vector<unsigned char>(PNG_IMAGE_SIZE(img))};
  if (!png_image_finish_read(&img, nullptr, out.rgb.data(), 0, nullptr)) {
    png_image_free(&img);
    throw InputError(file.string(), std::string("unreadable PNG: ") + img.message);
  }
  return out;
}

}  // namespace brdfkit::render
