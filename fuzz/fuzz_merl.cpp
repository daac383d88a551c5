// libFuzzer target: the MERL .binary reader (measured/merl.h merl::read, through read_merl) and
// look-ups on the table it returns.
//
// A MERL file is 34 992 012 bytes, far beyond what a fuzzer mutates, so byte 0 of the input picks
// how the file is built and the rest (the payload) says what goes into it:
//   kind 0: the payload is the whole file (header, truncation and trailing-byte checks);
//   kind 1: a full-size file with a valid header, every value 1.0 (measured);
//   kind 2: the same with every value −1 (not measured).
// For kinds 1 and 2 the payload is: one signed byte, the file's size relative to the full size
// (−16…+15 bytes), then records of a uint32 value index (mod 3·1 458 000) and a float64 written
// at that index. The full-size files are written once and patched in place per run, then restored.
#include <unistd.h>

#include <array>
#include <vector>

#include "brdfkit/measured/merl.h"
#include "brdfkit/measured/merl_brdf.h"
#include "fuzz_input.h"

namespace {

using namespace brdfkit;

// A full-size MERL file of one value everywhere, kept open for patching.
struct BaseFile {
  fuzz::ScratchFile file;
  double value;
};

BaseFile make_base(double value, std::string_view name) {
  BaseFile b{fuzz::scratch_file(name), value};
  const std::int32_t dims[3] = {merl::kResThetaH, merl::kResThetaD, merl::kResPhiD};
  const std::vector<double> values(3 * merl::kCellCount, value);
  if (::pwrite(b.file.fd, dims, sizeof dims, 0) != ssize_t(sizeof dims) ||
      ::pwrite(b.file.fd, values.data(), values.size() * sizeof(double), merl::kHeaderBytes) !=
          ssize_t(values.size() * sizeof(double)))
    std::abort();
  return b;
}

BaseFile& base(int kind) {
  static std::array<BaseFile, 2> files{make_base(1.0, ".measured.binary"), make_base(-1.0, ".unmeasured.binary")};
  return files[size_t(kind - 1)];
}

off_t value_offset(std::uint32_t index) {
  return off_t(merl::kHeaderBytes + (index % (3 * merl::kCellCount)) * sizeof(double));
}

void write_value(int fd, off_t at, double v) {
  if (::pwrite(fd, &v, sizeof v, at) != ssize_t(sizeof v)) std::abort();
}

// Reads the table and looks it up.
void read_and_look_up(const std::filesystem::path& file) {
  fuzz::expect_input_errors_naming(file, [&] {
    const std::unique_ptr<MerlBrdf> brdf = read_merl(file);
    for (const auto& [wi, wo] : fuzz::direction_pairs()) {
      (void)brdf->eval(wi, wo);
      (void)brdf->eval_trilinear(wi, wo);
    }
  });
}

// Kinds 1 and 2: patch the base file, read it, restore it.
void run_full_size(int kind, fuzz::Bytes& in) {
  BaseFile& b = base(kind);
  const int delta = int(std::int8_t(in.u8())) / 8;  // −16…+15 bytes
  std::vector<off_t> patched;
  while (in.left() >= 12) {
    const off_t at = value_offset(in.u32());
    write_value(b.file.fd, at, in.f64());
    patched.push_back(at);
  }
  if (delta != 0 && ::ftruncate(b.file.fd, off_t(merl::kFileBytes) + delta) != 0) std::abort();
  read_and_look_up(b.file.path);
  for (off_t at : patched) write_value(b.file.fd, at, b.value);
  if (delta != 0) {
    if (::ftruncate(b.file.fd, off_t(merl::kFileBytes)) != 0) std::abort();
    // A shorter file lost its last values: write them back.
    for (off_t at = off_t(merl::kFileBytes) - 16; at < off_t(merl::kFileBytes); at += 8) write_value(b.file.fd, at, b.value);
  }
}

}  // namespace

// The full-size files are written here, before the first input, so writing 70 MB does not count
// against that input's -timeout.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  base(1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const int kind = data[0] % 3;
  fuzz::Bytes payload(data + 1, size - 1);
  if (kind == 0) {
    const auto& file = fuzz::write_input(data + 1, size - 1);
    read_and_look_up(file);
  } else {
    run_full_size(kind, payload);
  }
  return 0;
}
