#include "brdfkit/measured/tensor_file_writer.h"

#include <cstring>
#include <stdexcept>

namespace brdfkit {

namespace {
// Struct::Type codes of Mitsuba 3 (as measured/rgl_tensor.cpp reads them).
constexpr std::uint8_t kUInt8 = 1, kFloat32 = 10;

template <class T> void put(std::string& out, T value) {
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));  // the format is little-endian, as every host brdfkit builds for
  out.append(b, sizeof(T));
}

std::uint64_t count(const std::vector<std::uint64_t>& shape) {
  std::uint64_t n = 1;
  for (auto s : shape) n *= s;
  return n;
}
}  // namespace

void TensorFileWriter::add(Field f) { fields_.push_back(std::move(f)); }

void TensorFileWriter::add_text(const std::string& name, const std::string& text) {
  add({name, kUInt8, {text.size()}, text});
}

void TensorFileWriter::add_u8(const std::string& name, const std::vector<std::uint64_t>& shape,
                              const std::vector<std::uint8_t>& data) {
  if (count(shape) != data.size()) throw std::logic_error("tensor_file field '" + name + "': shape and data disagree");
  add({name, kUInt8, shape, std::string(data.begin(), data.end())});
}

void TensorFileWriter::add_f32(const std::string& name, const std::vector<std::uint64_t>& shape,
                               const std::vector<float>& data) {
  if (count(shape) != data.size()) throw std::logic_error("tensor_file field '" + name + "': shape and data disagree");
  std::string bytes;
  for (float x : data) put(bytes, x);
  add({name, kFloat32, shape, std::move(bytes)});
}

std::string TensorFileWriter::bytes() const {
  std::string header("tensor_file\0", 12);
  put<std::uint8_t>(header, 1);
  put<std::uint8_t>(header, 0);
  put<std::uint32_t>(header, std::uint32_t(fields_.size()));
  std::uint64_t header_size = header.size();
  for (const Field& f : fields_) header_size += 2 + f.name.size() + 2 + 1 + 8 + 8 * f.shape.size();
  auto align = [](std::uint64_t x) { return (x + 7) / 8 * 8; };
  std::uint64_t offset = align(header_size);
  std::string body;
  for (const Field& f : fields_) {
    put<std::uint16_t>(header, std::uint16_t(f.name.size()));
    header += f.name;
    put<std::uint16_t>(header, std::uint16_t(f.shape.size()));
    put<std::uint8_t>(header, f.type);
    put<std::uint64_t>(header, offset);
    for (auto s : f.shape) put<std::uint64_t>(header, s);
    body.resize(offset - align(header_size), '\0');
    body += f.data;
    offset = align(align(header_size) + body.size());
  }
  header.resize(align(header_size), '\0');
  return header + body;
}

}  // namespace brdfkit
