#pragma once
// MERL isotropic BRDF tables (Matusik et al. 2003): the binary format, the reference reader's
// look-up and the table of raw values with its validity mask (DESIGN.md §2).
//
// File: three int32 (90, 90, 180) = resolutions of (θh, θd, φd), then 3 × 1 458 000 float64 in
// channel blocks R, G, B; cell (iθh, iθd, iφd) is at iφd + 180·(iθd + 90·iθh) in each block; ρ =
// stored value × 1/1500, 1.15/1500, 1.66/1500 (R, G, B). A negative stored value means "not
// measured": a cell is valid only when all three of its stored values are ≥ 0, and invalid cells
// are never returned by a look-up (nullopt), so no caller can use them by accident.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "brdfkit/core/half_diff.h"
#include "brdfkit/core/vec.h"

namespace brdfkit::merl {

inline constexpr int kResThetaH = 90, kResThetaD = 90, kResPhiD = 180;
inline constexpr size_t kCellCount = size_t(kResThetaH) * kResThetaD * kResPhiD;  // 1 458 000
inline constexpr size_t kHeaderBytes = 3 * sizeof(std::int32_t);
inline constexpr size_t kFileBytes = kHeaderBytes + 3 * kCellCount * sizeof(double);  // 34 992 012
// Stored value → sr⁻¹ per channel (MERL's BRDFRead.cpp RED_SCALE, GREEN_SCALE, BLUE_SCALE).
inline constexpr double kScale[3] = {1.0 / 1500.0, 1.15 / 1500.0, 1.66 / 1500.0};

struct Cell {
  int theta_h, theta_d, phi_d;
  friend bool operator==(const Cell&, const Cell&) = default;
};

// Position of a cell within one channel block (DESIGN.md §2).
constexpr size_t cell_offset(const Cell& c) {
  return size_t(c.phi_d) + size_t(kResPhiD) * (size_t(c.theta_d) + size_t(kResThetaD) * size_t(c.theta_h));
}
constexpr Cell cell_at(size_t offset) {
  return {int(offset / (size_t(kResPhiD) * kResThetaD)), int(offset / kResPhiD % kResThetaD),
          int(offset % kResPhiD)};
}

// The reference reader's floor rule (BRDFRead.cpp theta_half_index / theta_diff_index /
// phi_diff_index), with its operation order so results agree bit for bit; see merl.cpp.
int theta_h_index(double theta_h);
int theta_d_index(double theta_d);
int phi_d_index(double phi_d);
Cell cell_of(double theta_h, double theta_d, double phi_d);
Cell cell_of(const Vec3d& wi, const Vec3d& wo);  // through to_half_diff (MERL's rotations)

// The angles a cell stands for: its centre in index space (DESIGN.md §2, ALTA's convention),
// θh = ((i+½)/90)²·π/2, θd = (j+½)/90·π/2, φd = (k+½)/180·π, with φh = 0.
HalfDiff cell_centre(const Cell& c);
// Direction pair of the cell centre; false when either direction is at or below the horizon.
bool cell_directions(const Cell& c, Vec3d& wi, Vec3d& wo);

// Continuous index coordinates in which cell centres sit at integers (for trilinear look-up):
// x = 90·√(θh/(π/2)) − ½, y = θd/(π/2)·90 − ½, z = φd/π·180 − ½ (φd < 0 → φd + π first).
Vec3d index_coordinates(double theta_h, double theta_d, double phi_d);

// Raw stored values of a full table and its validity mask.
class Table {
 public:
  // A table with every cell not measured (raw −1, as real files store unmeasured cells).
  Table();
  // Takes ownership of 3·kCellCount raw values in channel blocks; computes the mask. Non-finite
  // values are the caller's to reject first (read() does).
  explicit Table(std::unique_ptr<double[]> raw);
  Table(const Table& other);
  Table(Table&&) noexcept = default;
  Table& operator=(Table other) noexcept;

  double raw(int channel, size_t offset) const { return raw_[size_t(channel) * kCellCount + offset]; }
  const double* raw_data() const { return raw_.get(); }  // 3·kCellCount values, channel blocks R, G, B
  // Sets the three raw values of a cell and its validity (all three ≥ 0). Distinct cells may be
  // set from different threads.
  void set_raw(size_t offset, double r, double g, double b);

  bool valid(size_t offset) const { return valid_[offset] != 0; }
  size_t valid_count() const;
  // ρ in sr⁻¹ (raw × scale) of a cell, whether valid or not.
  Rgb value(size_t offset) const {
    return {raw(0, offset) * kScale[0], raw(1, offset) * kScale[1], raw(2, offset) * kScale[2]};
  }

  // Nearest-cell look-up with the reference floor rule; nullopt for an invalid cell and, for
  // direction pairs, when either direction is at or below the horizon.
  std::optional<Rgb> lookup(double theta_h, double theta_d, double phi_d) const;
  std::optional<Rgb> lookup(const Vec3d& wi, const Vec3d& wo) const;
  // Trilinear interpolation in index_coordinates(): θh and θd clamp at the first and last cell
  // centres, φd wraps (φd and φd + π are the same cell by reciprocity). Corners that are not
  // measured are left out and the weights of the others renormalized; nullopt when no corner
  // with a non-zero weight is valid.
  std::optional<Rgb> lookup_trilinear(double theta_h, double theta_d, double phi_d) const;
  std::optional<Rgb> lookup_trilinear(const Vec3d& wi, const Vec3d& wo) const;

 private:
  // read() computes the mask in the pass that checks the values.
  friend Table read(const std::filesystem::path& file);
  Table(std::unique_ptr<double[]> raw, std::unique_ptr<std::uint8_t[]> valid)
      : raw_(std::move(raw)), valid_(std::move(valid)) {}

  std::unique_ptr<double[]> raw_;
  std::unique_ptr<std::uint8_t[]> valid_;
};

// Reads a MERL .binary file in one read, validating header, size and values; throws InputError
// naming the file and the problem (missing, unreadable, a directory, truncated, trailing bytes,
// wrong dimensions, NaN or ±Inf, a value above kMaxMeasuredValue once scaled, no measured cell).
// Requires a little-endian host, as the files are.
Table read(const std::filesystem::path& file);
// Writes the table atomically (core/atomic_file.h): bytes round-trip exactly through read().
void write(const std::filesystem::path& file, const Table& table);

}  // namespace brdfkit::merl
