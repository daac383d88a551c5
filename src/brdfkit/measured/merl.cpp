#include "brdfkit/measured/merl.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <functional>
#include <limits>
#include <numeric>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "brdfkit/core/atomic_file.h"
#include "brdfkit/core/error.h"
#include "brdfkit/measured/value_limit.h"

namespace brdfkit::merl {

static_assert(std::endian::native == std::endian::little, "MERL files are little-endian; add byte swapping");

// MERL BRDFRead.cpp theta_half_index: sqrt((θh/(π/2)·90)·90), i.e. 90·√(θh/(π/2)) (DESIGN.md §2)
// computed in the reference's order, so values at a cell edge land in the same cell as there.
int theta_h_index(double theta_h) {
  if (!(theta_h > 0.0)) return 0;
  const double deg = theta_h / (kPi / 2.0) * kResThetaH;
  const double t = std::sqrt(deg * kResThetaH);
  if (!(t < kResThetaH)) return kResThetaH - 1;  // also catches +Inf
  return int(t);
}

// BRDFRead.cpp theta_diff_index: floor(θd/(π·0.5)·90), clamped.
int theta_d_index(double theta_d) {
  const double t = theta_d / (kPi * 0.5) * kResThetaD;
  if (!(t > 0.0)) return 0;
  if (!(t < kResThetaD - 1)) return kResThetaD - 1;
  return int(t);
}

// BRDFRead.cpp phi_diff_index: φd < 0 → φd + π (reciprocity), floor(φd/π·360/2), clamped. The
// reference's /2 after ×360 is exact, so ×180 gives the same double.
int phi_d_index(double phi_d) {
  if (phi_d < 0.0) phi_d += kPi;
  const double t = phi_d / kPi * kResPhiD;
  if (!(t > 0.0)) return 0;
  if (!(t < kResPhiD - 1)) return kResPhiD - 1;
  return int(t);
}

Cell cell_of(double theta_h, double theta_d, double phi_d) {
  return {theta_h_index(theta_h), theta_d_index(theta_d), phi_d_index(phi_d)};
}

Cell cell_of(const Vec3d& wi, const Vec3d& wo) {
  const HalfDiff hd = to_half_diff(wi, wo);
  return cell_of(hd.theta_h, hd.theta_d, hd.phi_d);
}

HalfDiff cell_centre(const Cell& c) {
  const double u = (c.theta_h + 0.5) / kResThetaH;
  HalfDiff hd;
  hd.theta_h = u * u * (kPi / 2);
  hd.phi_h = 0;
  hd.theta_d = (c.theta_d + 0.5) / kResThetaD * (kPi / 2);
  hd.phi_d = (c.phi_d + 0.5) / kResPhiD * kPi;
  return hd;
}

bool cell_directions(const Cell& c, Vec3d& wi, Vec3d& wo) {
  from_half_diff(cell_centre(c), wi, wo);
  return wi.z() > 0 && wo.z() > 0;
}

Vec3d index_coordinates(double theta_h, double theta_d, double phi_d) {
  if (phi_d < 0) phi_d += kPi;
  return {kResThetaH * std::sqrt(std::max(theta_h, 0.0) / (kPi / 2)) - 0.5, theta_d / (kPi / 2) * kResThetaD - 0.5,
          phi_d / kPi * kResPhiD - 0.5};
}

// ---------------------------------------------------------------------------------------------

Table::Table()
    : raw_(std::make_unique_for_overwrite<double[]>(3 * kCellCount)),
      valid_(std::make_unique<std::uint8_t[]>(kCellCount)) {
  std::fill_n(raw_.get(), 3 * kCellCount, -1.0);
}

namespace {
// Cells per task of the passes over a whole table: a file's read is the one serial step before
// them, and each pass is memory-bound, so two cores halve it.
constexpr size_t kCellsPerTask = size_t(1) << 16;
tbb::blocked_range<size_t> all_cells() { return {0, kCellCount, kCellsPerTask}; }

// A cell is measured when all three of its stored values are ≥ 0 (DESIGN.md §2).
std::uint8_t measured_cell(double r, double g, double b) { return (r >= 0) & (g >= 0) & (b >= 0); }
}  // namespace

Table::Table(std::unique_ptr<double[]> raw)
    : raw_(std::move(raw)), valid_(std::make_unique_for_overwrite<std::uint8_t[]>(kCellCount)) {
  const double *r = raw_.get(), *g = r + kCellCount, *b = g + kCellCount;
  std::uint8_t* v = valid_.get();
  tbb::parallel_for(all_cells(), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t k = range.begin(); k < range.end(); ++k) v[k] = measured_cell(r[k], g[k], b[k]);
  });
}

Table::Table(const Table& other)
    : raw_(std::make_unique_for_overwrite<double[]>(3 * kCellCount)),
      valid_(std::make_unique_for_overwrite<std::uint8_t[]>(kCellCount)) {
  std::copy_n(other.raw_.get(), 3 * kCellCount, raw_.get());
  std::copy_n(other.valid_.get(), kCellCount, valid_.get());
}

Table& Table::operator=(Table other) noexcept {
  std::swap(raw_, other.raw_);
  std::swap(valid_, other.valid_);
  return *this;
}

void Table::set_raw(size_t offset, double r, double g, double b) {
  raw_[offset] = r;
  raw_[kCellCount + offset] = g;
  raw_[2 * kCellCount + offset] = b;
  valid_[offset] = measured_cell(r, g, b);
}

size_t Table::valid_count() const {
  const std::uint8_t* v = valid_.get();
  return tbb::parallel_reduce(
      all_cells(), size_t(0),
      [&](const tbb::blocked_range<size_t>& range, size_t n) {
        return n + size_t(std::count(v + range.begin(), v + range.end(), std::uint8_t(1)));
      },
      std::plus<>());
}

std::optional<Rgb> Table::lookup(double theta_h, double theta_d, double phi_d) const {
  const size_t k = cell_offset(cell_of(theta_h, theta_d, phi_d));
  if (!valid(k)) return std::nullopt;
  return value(k);
}

std::optional<Rgb> Table::lookup(const Vec3d& wi, const Vec3d& wo) const {
  if (!(wi.z() > 0 && wo.z() > 0)) return std::nullopt;
  const HalfDiff hd = to_half_diff(wi, wo);
  return lookup(hd.theta_h, hd.theta_d, hd.phi_d);
}

std::optional<Rgb> Table::lookup_trilinear(double theta_h, double theta_d, double phi_d) const {
  const Vec3d x = index_coordinates(theta_h, theta_d, phi_d);
  // θh, θd: clamp to the first/last centre (no data beyond them). φd: periodic with period 180.
  const double xh = std::clamp(x[0], 0.0, double(kResThetaH - 1));
  const double xd = std::clamp(x[1], 0.0, double(kResThetaD - 1));
  const int h0 = std::min(int(xh), kResThetaH - 2), d0 = std::min(int(xd), kResThetaD - 2);
  const double th = xh - h0, td = xd - d0;
  const double p0f = std::floor(x[2]);
  const double tp = x[2] - p0f;
  const int p0 = ((int(p0f) % kResPhiD) + kResPhiD) % kResPhiD, p1 = (p0 + 1) % kResPhiD;
  Rgb sum = Rgb::Zero();
  double wsum = 0;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      for (int c = 0; c < 2; ++c) {
        const double w = (a ? th : 1 - th) * (b ? td : 1 - td) * (c ? tp : 1 - tp);
        if (w == 0) continue;
        const size_t k = cell_offset({h0 + a, d0 + b, c ? p1 : p0});
        if (!valid(k)) continue;
        sum += w * value(k);
        wsum += w;
      }
  if (wsum == 0) return std::nullopt;
  return sum / wsum;
}

std::optional<Rgb> Table::lookup_trilinear(const Vec3d& wi, const Vec3d& wo) const {
  if (!(wi.z() > 0 && wo.z() > 0)) return std::nullopt;
  const HalfDiff hd = to_half_diff(wi, wo);
  return lookup_trilinear(hd.theta_h, hd.theta_d, hd.phi_d);
}

// ---------------------------------------------------------------------------------------------

namespace {

// Closes the descriptor on every path out of read().
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

// Reads exactly n bytes at file offset `at` (pread(2) may return less; it leaves the descriptor's
// offset alone, so pieces can be read in parallel); returns how many were read.
size_t pread_fully(int fd, void* dst, size_t n, off_t at) {
  auto* p = static_cast<char*>(dst);
  size_t done = 0;
  while (done < n) {
    const ssize_t got = ::pread(fd, p + done, n - done, at + off_t(done));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;
    done += size_t(got);
  }
  return done;
}
constexpr size_t kReadPiece = size_t(4) << 20;  // bytes per pread task

const char* const kChannelName[3] = {"R", "G", "B"};

// The limit on a raw value of channel c: kMaxMeasuredValue once scaled.
constexpr double kRawLimit[3] = {kMaxMeasuredValue / kScale[0], kMaxMeasuredValue / kScale[1],
                                 kMaxMeasuredValue / kScale[2]};

// MERL files are refused, not patched, for a value that cannot be a measurement: non-finite, or
// above kMaxMeasuredValue once scaled, where means and albedos overflow. The format has its own
// "not measured" mark (a negative value); anything else is corruption, and dropping those cells
// would pass a damaged file off as a sparse measurement.
// (−∞ < raw ≤ kRawLimit[c] is false for NaN: the same test without isfinite's branch.)
bool is_measurement(double raw, size_t c) {
  return (raw > -std::numeric_limits<double>::infinity()) & (raw <= kRawLimit[c]);
}

// Index of the first value (channel blocks R, G, B) that is no measurement; 3·kCellCount if none.
// Each task scans its cells branch-free and searches only where one fails; the least index wins,
// so the answer does not depend on the tasks' order.
size_t first_corrupt_value(const double* v) {
  constexpr size_t kNone = 3 * kCellCount;
  for (size_t c = 0; c < 3; ++c) {
    const double* block = v + c * kCellCount;
    const size_t first = tbb::parallel_reduce(
        all_cells(), kNone,
        [&](const tbb::blocked_range<size_t>& range, size_t found) {
          bool all = true;
          for (size_t k = range.begin(); k < range.end(); ++k) all &= is_measurement(block[k], c);
          if (all) return found;
          const double* bad = std::find_if_not(block + range.begin(), block + range.end(),
                                               [&](double x) { return is_measurement(x, c); });
          return std::min(found, c * kCellCount + size_t(bad - block));
        },
        [](size_t a, size_t b) { return std::min(a, b); });
    if (first != kNone) return first;
  }
  return kNone;
}

// One pass over the cells: each cell's validity (Table's mask) into `valid`, and whether every
// value is a measurement (the least index of one that is not is then first_corrupt_value's to find).
bool mask_measured(const double* v, std::uint8_t* valid) {
  const double *r = v, *g = r + kCellCount, *b = g + kCellCount;
  return tbb::parallel_reduce(
      all_cells(), true,
      [&](const tbb::blocked_range<size_t>& range, bool ok) {
        bool all = true;
        for (size_t k = range.begin(); k < range.end(); ++k) {
          valid[k] = measured_cell(r[k], g[k], b[k]);
          all &= is_measurement(r[k], 0) & is_measurement(g[k], 1) & is_measurement(b[k], 2);
        }
        return ok && all;
      },
      std::logical_and<>());
}

[[noreturn]] void refuse_value(const std::string& where, double x, size_t k) {
  const Cell c = cell_at(k % kCellCount);
  const std::string what = std::isnan(x)   ? "NaN"
                           : std::isinf(x) ? (x > 0 ? "+Inf" : "-Inf")
                                           : fmt::format("{}, above {} sr⁻¹ once scaled: not a measurement", x, kMaxMeasuredValue);
  throw InputError(where, fmt::format("value {} ({} channel, cell θh {} θd {} φd {}) is {}", k, kChannelName[k / kCellCount], c.theta_h,
                                      c.theta_d, c.phi_d, what));
}

}  // namespace

Table read(const std::filesystem::path& file) {
  const std::string where = file.string();
  Fd f{::open(file.c_str(), O_RDONLY | O_CLOEXEC)};
  if (f.fd < 0) {
    const int e = errno;
    if (e == ENOENT) throw InputError(where, "no such file");
    throw InputError(where, fmt::format("cannot open: {}", std::strerror(e)));
  }
  struct stat st {};
  if (::fstat(f.fd, &st) != 0) throw InputError(where, fmt::format("cannot stat: {}", std::strerror(errno)));
  if (S_ISDIR(st.st_mode)) throw InputError(where, "is a directory, not a MERL file");
  if (!S_ISREG(st.st_mode)) throw InputError(where, "not a regular file");
  const auto size = std::uintmax_t(st.st_size);
  if (size < kHeaderBytes)
    throw InputError(where, fmt::format("truncated: {} bytes, shorter than the 12-byte MERL header", size));

  std::int32_t dims[3];
  if (pread_fully(f.fd, dims, sizeof dims, 0) != sizeof dims)
    throw InputError(where, fmt::format("read error in the header: {}", std::strerror(errno)));
  if (dims[0] != kResThetaH || dims[1] != kResThetaD || dims[2] != kResPhiD)
    throw InputError(where, fmt::format("header dimensions ({}, {}, {}), expected (90, 90, 180) for (θh, θd, φd)",
                                        dims[0], dims[1], dims[2]));
  if (size < kFileBytes)
    throw InputError(where, fmt::format("truncated: {} bytes, a 90 x 90 x 180 MERL file has {}", size, kFileBytes));
  if (size > kFileBytes)
    throw InputError(where, fmt::format("{} trailing bytes after the 3 x 1458000 values ({} bytes, expected {})",
                                        size - kFileBytes, size, kFileBytes));

  // Read straight into the table's storage (no intermediate buffer, no per-value copy), in pieces
  // on every core: the copy out of the page cache and the faults of the fresh pages are the cost.
  auto raw = std::make_unique_for_overwrite<double[]>(3 * kCellCount);
  const size_t want = 3 * kCellCount * sizeof(double);
  std::atomic<size_t> got = 0;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, want, kReadPiece), [&](const tbb::blocked_range<size_t>& r) {
    got += pread_fully(f.fd, reinterpret_cast<char*>(raw.get()) + r.begin(), r.size(), off_t(kHeaderBytes + r.begin()));
  });
  if (got != want)
    throw InputError(where, fmt::format("truncated: read {} of {} value bytes", got.load(), want));

  auto valid = std::make_unique_for_overwrite<std::uint8_t[]>(kCellCount);
  if (!mask_measured(raw.get(), valid.get())) {
    const size_t k = first_corrupt_value(raw.get());
    refuse_value(where, raw[k], k);
  }
  Table table(std::move(raw), std::move(valid));
  if (table.valid_count() == 0)
    throw InputError(where, "no measured cell: every cell has a negative (not measured) value");
  return table;
}

void write(const std::filesystem::path& file, const Table& table) {
  write_file_atomically(file, [&](std::ostream& out) {
    const std::int32_t dims[3] = {kResThetaH, kResThetaD, kResPhiD};
    out.write(reinterpret_cast<const char*>(dims), sizeof dims);
    out.write(reinterpret_cast<const char*>(table.raw_data()), std::streamsize(3 * kCellCount * sizeof(double)));
  });
}

}  // namespace brdfkit::merl
