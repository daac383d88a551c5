#pragma once
// Mitsuba's `tensor_file` (the container of RGL BRDFs, Dupuy & Jakob 2018; Mitsuba 3
// src/core/tensor.cpp, layout in data/README.md): 12 bytes "tensor_file\0", version 1.0 (two
// uint8), uint32 field count, then per field uint16 name length, name, uint16 rank, uint8 type
// (Mitsuba's Struct::Type codes), uint64 data offset from the file start, one uint64 per
// dimension; the data follow, each field's block 8-byte aligned. Little-endian throughout.
#include <cstdint>
#include <string>
#include <vector>

namespace brdfkit {

class TensorFileWriter {
 public:
  void add_text(const std::string& name, const std::string& text);
  void add_u8(const std::string& name, const std::vector<std::uint64_t>& shape, const std::vector<std::uint8_t>& data);
  void add_f32(const std::string& name, const std::vector<std::uint64_t>& shape, const std::vector<float>& data);
  // The whole file, in the order the fields were added.
  std::string bytes() const;

 private:
  struct Field {
    std::string name;
    std::uint8_t type;
    std::vector<std::uint64_t> shape;
    std::string data;
  };
  void add(Field f);
  std::vector<Field> fields_;
};

}  // namespace brdfkit
