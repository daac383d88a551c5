#pragma once
// Helpers for the tests on the shared real measurements (../shared/data).
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "brdfkit/core/vec.h"
#include "support/test_util.h"

namespace brdfkit::test {

inline const std::vector<std::string> kRglMaterials = {"paper_white", "colodur_napoli_4f", "satin_rosaline", "vch_golden_yellow",
                                                      "cc_ibiza_sunset"};
inline const std::vector<std::string> kCornellMaterials = {"acryl_blue", "garnet_red", "krylon_blue"};

inline std::filesystem::path rgl_file(const std::string& name) { return data_dir() / "rgl" / (name + "_rgb.bsdf"); }
inline std::filesystem::path cornell_file(const std::string& name) { return data_dir() / "cornell" / (name + ".brdf"); }

// Linear-sRGB luminance Y (IEC 61966-2-1), the weights of the RGL `luminance` table.
inline double luminance(const Rgb& v) { return 0.212671 * v[0] + 0.715160 * v[1] + 0.072169 * v[2]; }

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

inline std::vector<std::uint8_t> read_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
inline void write_bytes(const std::filesystem::path& p, const std::vector<std::uint8_t>& b) {
  std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
}

// A tensor_file as fields, to build variants of the real files (data/README.md layout).
struct TensorField {
  std::string name;
  std::uint8_t type;
  std::vector<std::uint64_t> shape;
  std::vector<std::uint8_t> data;
};

inline std::vector<TensorField> parse_tensor(const std::vector<std::uint8_t>& b) {
  size_t pos = 14;
  auto get = [&](size_t n) {
    std::uint64_t v = 0;
    for (size_t k = 0; k < n; ++k) v |= std::uint64_t(b.at(pos + k)) << (8 * k);
    pos += n;
    return v;
  };
  const auto count = get(4);
  std::vector<TensorField> fields;
  for (std::uint64_t i = 0; i < count; ++i) {
    TensorField f;
    const auto len = get(2);
    f.name.assign(reinterpret_cast<const char*>(b.data() + pos), len);
    pos += len;
    const auto ndim = get(2);
    f.type = std::uint8_t(get(1));
    const auto offset = get(8);
    size_t n = f.type == 10 || f.type == 5 ? 4 : 1;
    for (std::uint64_t d = 0; d < ndim; ++d) {
      f.shape.push_back(get(8));
      n *= f.shape.back();
    }
    f.data.assign(b.begin() + std::ptrdiff_t(offset), b.begin() + std::ptrdiff_t(offset + n));
    fields.push_back(std::move(f));
  }
  return fields;
}

inline std::vector<std::uint8_t> write_tensor(const std::vector<TensorField>& fields) {
  std::vector<std::uint8_t> b(12 + 2 + 4);
  std::memcpy(b.data(), "tensor_file\0", 12);
  b[12] = 1;
  b[13] = 0;
  auto put = [&](std::vector<std::uint8_t>& out, std::uint64_t v, size_t n) {
    for (size_t k = 0; k < n; ++k) out.push_back(std::uint8_t(v >> (8 * k)));
  };
  std::vector<std::uint8_t> tmp;
  put(tmp, fields.size(), 4);
  std::copy(tmp.begin(), tmp.end(), b.begin() + 14);
  size_t header = b.size();
  for (const auto& f : fields) header += 2 + f.name.size() + 2 + 1 + 8 + 8 * f.shape.size();
  size_t offset = (header + 7) / 8 * 8;
  std::vector<size_t> offsets;
  for (const auto& f : fields) {
    offsets.push_back(offset);
    offset = (offset + f.data.size() + 7) / 8 * 8;
  }
  for (size_t i = 0; i < fields.size(); ++i) {
    const auto& f = fields[i];
    put(b, f.name.size(), 2);
    b.insert(b.end(), f.name.begin(), f.name.end());
    put(b, f.shape.size(), 2);
    put(b, f.type, 1);
    put(b, offsets[i], 8);
    for (auto s : f.shape) put(b, s, 8);
  }
  b.resize(offset, 0);
  for (size_t i = 0; i < fields.size(); ++i) std::copy(fields[i].data.begin(), fields[i].data.end(), b.begin() + std::ptrdiff_t(offsets[i]));
  return b;
}

// Sets entry `index` (flat, row-major) of the float32 field `name`: one bad value in a real file.
inline void set_float(std::vector<TensorField>& fields, const std::string& name, size_t index, float value) {
  for (auto& f : fields)
    if (f.name == name) {
      ASSERT_LE(4 * (index + 1), f.data.size()) << name << " has no entry " << index;
      std::memcpy(f.data.data() + 4 * index, &value, sizeof value);
      return;
    }
  ADD_FAILURE() << "no field '" << name << "'";
}

// Sets every entry of the float32 field `name` to `value`.
inline void fill_float(std::vector<TensorField>& fields, const std::string& name, float value) {
  for (auto& f : fields)
    if (f.name == name)
      for (size_t i = 0; i + 4 <= f.data.size(); i += 4) std::memcpy(f.data.data() + i, &value, sizeof value);
}

// A copy of the real RGL file `material` with `change` applied to its fields, saved as `file`.
template <class Change>
std::filesystem::path rgl_variant(const std::string& material, const std::filesystem::path& file, Change change) {
  auto fields = parse_tensor(read_bytes(rgl_file(material)));
  change(fields);
  write_bytes(file, write_tensor(fields));
  return file;
}

}  // namespace brdfkit::test
