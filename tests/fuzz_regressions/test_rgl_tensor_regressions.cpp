// Inputs the RGL tensor_file fuzz target (fuzz/fuzz_rgl.cpp) and its review found, as small files
// built here: each must be refused with a one-line InputError naming the file and the field.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/rgl_tensor.h"

namespace brdfkit {
namespace {

constexpr std::uint8_t kUInt8 = 1, kFloat32 = 10;  // Mitsuba Struct::Type codes

struct TensorField {
  std::string name;
  std::uint8_t type;
  std::vector<std::uint64_t> shape;
  std::string data;
};

template <class T> void put(std::string& out, T v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); }

std::string floats(const std::vector<float>& v) {
  std::string s(v.size() * sizeof(float), '\0');
  std::memcpy(s.data(), v.data(), s.size());
  return s;
}

// A tensor_file (measured/rgl_tensor.h): magic, version 1.0, the field table, then the data of
// each field in order.
std::string tensor_file(const std::vector<TensorField>& fields) {
  auto header = [&](const std::vector<std::uint64_t>& offsets) {
    std::string h("tensor_file\0\x01\x00", 14);
    put(h, std::uint32_t(fields.size()));
    for (size_t k = 0; k < fields.size(); ++k) {
      put(h, std::uint16_t(fields[k].name.size()));
      h += fields[k].name;
      put(h, std::uint16_t(fields[k].shape.size()));
      put(h, fields[k].type);
      put(h, offsets[k]);
      for (std::uint64_t s : fields[k].shape) put(h, s);
    }
    return h;
  };
  std::vector<std::uint64_t> offsets(fields.size());
  std::uint64_t pos = header(offsets).size();  // the header's size does not depend on the offsets
  for (size_t k = 0; k < fields.size(); ++k) {
    offsets[k] = pos;
    pos += fields[k].data.size();
  }
  std::string out = header(offsets);
  for (const TensorField& f : fields) out += f.data;
  return out;
}

// Two θi nodes and 2 × 2 tables: the smallest file the reader accepts, with an `rgb` table.
std::vector<TensorField> valid_fields() {
  return {{"theta_i", kFloat32, {2}, floats({0.0f, 0.5f})},
          {"phi_i", kFloat32, {1}, floats({0.0f})},
          {"sigma", kFloat32, {2, 2}, floats({1, 1, 1, 1})},
          {"ndf", kFloat32, {2, 2}, floats({2, 1, 1, 0.5f})},
          {"vndf", kFloat32, {1, 2, 2, 2}, floats({1, 2, 1, 1, 1, 1, 2, 1})},
          {"luminance", kFloat32, {1, 2, 2, 2}, floats({0.2f, 0.3f, 0.2f, 0.1f, 0.2f, 0.3f, 0.2f, 0.1f})},
          {"jacobian", kUInt8, {1}, std::string(1, '\1')},
          {"rgb", kFloat32, {1, 2, 3, 2, 2}, floats(std::vector<float>(24, 0.25f))}};
}

std::filesystem::path write_file(const std::string& name, const std::string& bytes) {
  const auto path = std::filesystem::path(::testing::TempDir()) / (name + "-" + std::to_string(::getpid()) + ".bsdf");
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// The reader's InputError message for `bytes`, or a note that it threw none.
std::string error_of(const std::string& name, const std::string& bytes) {
  const auto path = write_file(name, bytes);
  std::string message = "no InputError";
  try {
    const RglBrdf brdf(path);
  } catch (const InputError& e) {
    message = e.what();
  }
  std::filesystem::remove(path);
  return message;
}

TEST(RglFuzzRegressions, TheValidFileOfTheseTestsReads) {
  const auto path = write_file("rgl-valid", tensor_file(valid_fields()));
  const RglBrdf brdf(path);
  EXPECT_EQ(brdf.grid_size(), 2);
  EXPECT_EQ(brdf.theta_i().size(), 2u);
  EXPECT_DOUBLE_EQ(brdf.rgb_node(1, 1, 1)[2], 0.25);
  std::filesystem::remove(path);
}

// A table with a zero dimension holds no entries; copying them passed memcpy the null data() of
// an empty vector (undefined behaviour, UBSan: "null pointer passed as argument 1"). The shape is
// then refused by the table's own check.
TEST(RglFuzzRegressions, TableWithAZeroDimensionIsRefusedByItsShape) {
  auto fields = valid_fields();
  fields.back().shape = {1, 2, 3, 0, 2};
  fields.back().data.clear();
  const std::string message = error_of("rgl-zero-dim", tensor_file(fields));
  EXPECT_NE(message.find("rgl-zero-dim"), std::string::npos) << message;
  EXPECT_NE(message.find("field 'rgb' has shape [1,2,3,0,2], expected [1,2,3,2,2]"), std::string::npos) << message;
}

// 2^24 × 2^24 × 2^14 float32 entries are 2^64 bytes, 0 once the size wraps: the field passed the
// "fits in the file" check and its copy asked for a vector of 2^62 floats (std::length_error, an
// internal error). With a 2^16-node θi axis, `luminance`, `vndf` and `rgb` of 2^24 × 2^24 grids
// wrap to 0 entries while their shapes still drive the copy loops, which then read at indices up to
// 2^64 from an empty table.
TEST(RglFuzzRegressions, FieldWhoseSizeWrapsIsTruncation) {
  auto fields = valid_fields();
  fields.push_back({"wavelengths", kFloat32, {1u << 24, 1u << 24, 1u << 14}, ""});
  const std::string message = error_of("rgl-wrap", tensor_file(fields));
  EXPECT_NE(message.find("rgl-wrap"), std::string::npos) << message;
  EXPECT_NE(message.find("field 'wavelengths': data (shape [16777216,16777216,16384] of 4-byte entries at offset"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("extend past the end of the file"), std::string::npos) << message;
}

// `spectra` with an empty `wavelengths` field reached the spectral conversion, whose error named
// neither the file nor the field ("spectrum: no wavelengths").
TEST(RglFuzzRegressions, SpectraWithoutWavelengthsNameTheFileAndField) {
  auto fields = valid_fields();
  fields.pop_back();  // no rgb
  fields.push_back({"wavelengths", kFloat32, {0}, ""});
  fields.push_back({"spectra", kFloat32, {1, 2, 0, 2, 2}, ""});
  const std::string message = error_of("rgl-no-wavelengths", tensor_file(fields));
  EXPECT_NE(message.find("rgl-no-wavelengths"), std::string::npos) << message;
  EXPECT_NE(message.find("field 'wavelengths' is empty"), std::string::npos) << message;
}

}  // namespace
}  // namespace brdfkit
