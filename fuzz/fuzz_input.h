#pragma once
// What the fuzz targets share: the input as a file (the readers take paths), the input read piece
// by piece, direction pairs for look-ups, and the exception rule. An InputError naming the file
// is the readers' answer to bad input (the CLI prints it in one line and exits 2); any other
// exception escapes to libFuzzer, which reports it as a crash, because the CLI turns it into
// "internal error" (exit 1).
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "brdfkit/core/error.h"
#include "brdfkit/core/vec.h"

namespace brdfkit::fuzz {

// A file only this process sees and that vanishes with it however it ends (a crash skips atexit
// handlers, and MERL's are 35 MB in /dev/shm): created, unlinked at once, and read through
// /proc/self/fd/N, which opens the same file. In /dev/shm where it exists, so a run costs no disk I/O.
struct ScratchFile {
  int fd;
  std::filesystem::path path;
};

inline ScratchFile scratch_file(std::string_view name) {
  const std::filesystem::path dir = std::filesystem::is_directory("/dev/shm") ? "/dev/shm" : std::filesystem::temp_directory_path();
  const std::filesystem::path created = dir / ("brdfkit-fuzz-" + std::to_string(::getpid()) + std::string(name));
  const int fd = ::open(created.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (fd < 0 || ::unlink(created.c_str()) != 0) {
    std::perror(created.c_str());
    std::abort();  // the harness, not a reader, failed: stop rather than fuzz nothing
  }
  return {fd, "/proc/self/fd/" + std::to_string(fd)};
}

// Writes the input to the process's scratch file and returns the path to read it by.
inline const std::filesystem::path& write_input(const std::uint8_t* data, size_t size) {
  static const ScratchFile file = scratch_file(".input");
  if (::ftruncate(file.fd, 0) != 0 || (size > 0 && ::pwrite(file.fd, data, size, 0) != ssize_t(size))) {
    std::perror("writing the input");
    std::abort();
  }
  return file.path;
}

// Runs `f`; an InputError is the expected answer to bad input.
template <class F> void expect_input_errors(F&& f) {
  try {
    f();
  } catch (const InputError&) {
  }
}

// The same for a reader of `file`, whose one-line error must name the file (the CLI prints only
// the message): an InputError that does not is a bug, reported as a crash.
template <class F> void expect_input_errors_naming(const std::filesystem::path& file, F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    if (std::string_view(e.what()).find(file.string()) != std::string_view::npos) return;
    std::fprintf(stderr, "InputError does not name the file %s: %s\n", file.c_str(), e.what());
    std::abort();
  }
}

// The input read piece by piece, little-endian; zeros once it is used up.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, size_t size) : data_(data), size_(size) {}
  std::uint8_t u8() { return pos_ < size_ ? data_[pos_++] : 0; }
  std::uint16_t u16() {
    const unsigned lo = u8();
    return std::uint16_t(lo | (unsigned(u8()) << 8));
  }
  std::uint32_t u32() {
    const std::uint32_t lo = u16();
    return lo | (std::uint32_t(u16()) << 16);
  }
  double f64() {
    const std::uint64_t lo = u32();
    const std::uint64_t bits = lo | (std::uint64_t(u32()) << 32);
    double x;
    static_assert(sizeof x == sizeof bits);
    std::memcpy(&x, &bits, sizeof x);
    return x;
  }
  size_t left() const { return size_ - std::min(pos_, size_); }

 private:
  const std::uint8_t* data_;
  size_t size_, pos_ = 0;
};

// Direction pairs (wi, wo) for look-ups on what a reader returned: the normal, grazing angles, the
// horizon itself, mirror and retro-reflection pairs and a few in between.
inline const std::vector<std::pair<Vec3d, Vec3d>>& direction_pairs() {
  static const std::vector<std::pair<Vec3d, Vec3d>> pairs = [] {
    const double thetas[] = {0.0, 1e-9, 0.3, 0.8, 1.2, 1.5707, kPi / 2};
    const double phis[] = {0.0, 1.0, kPi, 4.0};
    std::vector<std::pair<Vec3d, Vec3d>> p;
    for (double ti : thetas)
      for (double to : thetas)
        for (double po : phis) p.emplace_back(spherical_direction(ti, 0.0), spherical_direction(to, po));
    return p;
  }();
  return pairs;
}

}  // namespace brdfkit::fuzz
