#include "brdfkit/measured/spectral_rgb.h"

#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/cie_tables.h"

namespace brdfkit {

namespace {

constexpr int kFirstNm = 360, kLastNm = 830, kCount = kLastNm - kFirstNm + 1;

constexpr const char* kCmfFile = "cie1931-2deg-xyz-1nm.csv";
constexpr const char* kD65File = "cie-d65-5nm.csv";
using Rows = std::vector<std::vector<double>>;

// One row of numbers separated by commas; `where` is the file and line for errors.
std::vector<double> parse_row(const std::string& line, const std::string& where, size_t columns) {
  std::vector<double> row;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) {
    try {
      row.push_back(std::stod(cell));
    } catch (const std::exception&) {
      throw InputError(where, "not a number: '" + cell + "'");
    }
  }
  if (row.size() != columns)
    throw InputError(where, "expected " + std::to_string(columns) + " values, found " + std::to_string(row.size()));
  return row;
}

// Rows of a CIE CSV table (`#` comment lines, one header line, then numbers separated by commas).
Rows read_csv(std::istream& in, const std::string& where, size_t columns) {
  Rows rows;
  std::string line;
  bool header_seen = false;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    if (!std::exchange(header_seen, true)) continue;
    rows.push_back(parse_row(line, where + ":" + std::to_string(line_no), columns));
  }
  if (rows.size() < 2) throw InputError(where, "CIE table has no data rows");
  return rows;
}

Rows read_csv_file(const std::filesystem::path& file, size_t columns) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string(), "cannot open CIE table");
  return read_csv(in, file.string(), columns);
}

// A table compiled into brdfkit (cie_tables.h), by file name.
Rows read_embedded(std::string_view name, size_t columns) {
  for (const auto& [file, text] : cie::embedded_tables())
    if (file == name) {
      std::istringstream in{std::string(text)};
      return read_csv(in, "built-in " + std::string(name), columns);
    }
  throw std::logic_error("CIE table " + std::string(name) + " was not compiled in (CMakeLists.txt)");
}

// Linear interpolation in a table sorted by its first column; constant beyond its ends.
double interpolate(const Rows& rows, size_t column, double x) {
  if (x <= rows.front()[0]) return rows.front()[column];
  if (x >= rows.back()[0]) return rows.back()[column];
  size_t lo = 0, hi = rows.size() - 1;
  while (hi - lo > 1) {
    const size_t mid = (lo + hi) / 2;
    (rows[mid][0] <= x ? lo : hi) = mid;
  }
  const double t = (x - rows[lo][0]) / (rows[hi][0] - rows[lo][0]);
  return (1 - t) * rows[lo][column] + t * rows[hi][column];
}

}  // namespace

Eigen::Matrix3d xyz_to_linear_srgb() {
  // IEC 61966-2-1:1999 (sRGB), XYZ (D65, Y = 1 white) → linear RGB.
  Eigen::Matrix3d m;
  m << 3.2406, -1.5372, -0.4986,  //
      -0.9689, 1.8758, 0.0415,    //
      0.0557, -0.2040, 1.0570;
  return m;
}

SpectrumToRgb::SpectrumToRgb() { set_weights(read_embedded(kCmfFile, 4), read_embedded(kD65File, 2), "built-in CIE tables"); }

SpectrumToRgb::SpectrumToRgb(const std::filesystem::path& cie_dir) {
  set_weights(read_csv_file(cie_dir / kCmfFile, 4), read_csv_file(cie_dir / kD65File, 2), cie_dir.string());
}

void SpectrumToRgb::set_weights(const Rows& cmf, const Rows& d65, const std::string& where) {
  if (cmf.front()[0] > kFirstNm || cmf.back()[0] < kLastNm || d65.front()[0] > kFirstNm || d65.back()[0] < kLastNm)
    throw InputError(where, "CIE tables must cover 360-830 nm");
  // DESIGN.md §2: XYZ = Σ S·D65·cmf / Σ D65·ȳ over 360–830 nm at 1 nm.
  double norm = 0;
  for (int k = 0; k < kCount; ++k) {
    const double nm = kFirstNm + k;
    const double e = interpolate(d65, 1, nm);
    for (int c = 0; c < 3; ++c) weights_(k, c) = e * interpolate(cmf, size_t(c) + 1, nm);
    norm += weights_(k, 1);
  }
  weights_ /= norm;
}

Eigen::MatrixXd SpectrumToRgb::matrix(std::span<const double> wl) const {
  const size_t n = wl.size();
  if (n == 0) throw InputError("spectrum", "no wavelengths");
  for (size_t j = 1; j < n; ++j)
    if (!(wl[j] > wl[j - 1])) throw InputError("spectrum", "wavelengths must increase");
  // S(λ) = Σ_j b_j(λ) S_j with hat functions, held constant outside [wl_0, wl_n−1] (DESIGN.md §2):
  // the conversion is linear in the samples, so it is one 3 × n matrix.
  Eigen::MatrixXd basis_xyz = Eigen::MatrixXd::Zero(3, Eigen::Index(n));
  size_t j = 0;
  for (int k = 0; k < kCount; ++k) {
    const double nm = kFirstNm + k;
    const Eigen::Vector3d w = weights_.row(k).transpose();
    if (n == 1 || nm <= wl[0]) {
      basis_xyz.col(0) += w;
    } else if (nm >= wl[n - 1]) {
      basis_xyz.col(Eigen::Index(n - 1)) += w;
    } else {
      while (wl[j + 1] < nm) ++j;
      const double t = (nm - wl[j]) / (wl[j + 1] - wl[j]);
      basis_xyz.col(Eigen::Index(j)) += (1 - t) * w;
      basis_xyz.col(Eigen::Index(j + 1)) += t * w;
    }
  }
  return xyz_to_linear_srgb() * basis_xyz;
}

Eigen::Vector3d SpectrumToRgb::xyz(std::span<const double> wl, std::span<const double> values) const {
  if (wl.size() != values.size()) throw InputError("spectrum", "wavelength and value counts differ");
  const Eigen::MatrixXd m = xyz_to_linear_srgb().inverse() * matrix(wl);
  return m * Eigen::Map<const Eigen::VectorXd>(values.data(), Eigen::Index(values.size()));
}

Rgb SpectrumToRgb::rgb(std::span<const double> wl, std::span<const double> values) const {
  if (wl.size() != values.size()) throw InputError("spectrum", "wavelength and value counts differ");
  const Eigen::Vector3d v = matrix(wl) * Eigen::Map<const Eigen::VectorXd>(values.data(), Eigen::Index(values.size()));
  return v.array();
}

const SpectrumToRgb& built_in_spectrum_to_rgb() {
  static const SpectrumToRgb built_in;
  return built_in;
}

const SpectrumToRgb& default_spectrum_to_rgb() {
  const char* env = std::getenv("BRDFKIT_CIE_DIR");
  if (!env || !*env) return built_in_spectrum_to_rgb();
  const std::filesystem::path dir(env);
  // An override that cannot be honoured is an error, not a silent fall-back to other numbers.
  for (const char* name : {kCmfFile, kD65File})
    if (!std::filesystem::is_regular_file(dir / name))
      throw InputError("BRDFKIT_CIE_DIR=" + dir.string(),
                       std::string("no ") + name + " in that folder (unset BRDFKIT_CIE_DIR to use the built-in CIE tables)");
  static std::mutex mutex;
  static std::map<std::filesystem::path, std::unique_ptr<SpectrumToRgb>> cache;
  const auto key = std::filesystem::weakly_canonical(dir);
  std::lock_guard lock(mutex);
  auto& slot = cache[key];
  if (!slot) slot = std::make_unique<SpectrumToRgb>(key);
  return *slot;
}

}  // namespace brdfkit
