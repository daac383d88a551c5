#include "brdfkit/measured/spectral_rgb.h"

#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include "brdfkit/core/error.h"

namespace brdfkit {

namespace {

constexpr int kFirstNm = 360, kLastNm = 830, kCount = kLastNm - kFirstNm + 1;

// Rows of a CIE CSV table (`#` comment lines, one header line, then numbers separated by commas).
std::vector<std::vector<double>> read_csv(const std::filesystem::path& file, size_t columns) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string(), "cannot open CIE table");
  std::vector<std::vector<double>> rows;
  std::string line;
  bool header_seen = false;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    if (!header_seen) {
      header_seen = true;
      continue;
    }
    std::vector<double> row;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) {
      try {
        size_t used = 0;
        row.push_back(std::stod(cell, &used));
      } catch (const std::exception&) {
        throw InputError(file.string() + ":" + std::to_string(line_no), "not a number: '" + cell + "'");
      }
    }
    if (row.size() != columns)
      throw InputError(file.string() + ":" + std::to_string(line_no),
                       "expected " + std::to_string(columns) + " values, found " + std::to_string(row.size()));
    rows.push_back(std::move(row));
  }
  if (rows.size() < 2) throw InputError(file.string(), "CIE table has no data rows");
  return rows;
}

// Linear interpolation in a table sorted by its first column; constant beyond its ends.
double interpolate(const std::vector<std::vector<double>>& rows, size_t column, double x) {
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

SpectrumToRgb::SpectrumToRgb(const std::filesystem::path& cie_dir) {
  const auto cmf = read_csv(cie_dir / "cie1931-2deg-xyz-1nm.csv", 4);
  const auto d65 = read_csv(cie_dir / "cie-d65-5nm.csv", 2);
  if (cmf.front()[0] > kFirstNm || cmf.back()[0] < kLastNm || d65.front()[0] > kFirstNm || d65.back()[0] < kLastNm)
    throw InputError(cie_dir.string(), "CIE tables must cover 360-830 nm");
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

std::filesystem::path default_cie_dir(const std::filesystem::path& data_file) {
  std::vector<std::filesystem::path> tried;
  auto holds_tables = [&](const std::filesystem::path& dir) {
    tried.push_back(dir);
    return std::filesystem::exists(dir / "cie1931-2deg-xyz-1nm.csv") && std::filesystem::exists(dir / "cie-d65-5nm.csv");
  };
  if (const char* env = std::getenv("BRDFKIT_CIE_DIR"); env && *env && holds_tables(env)) return env;
  if (const auto sibling = std::filesystem::absolute(data_file).parent_path().parent_path() / "cie"; holds_tables(sibling))
    return sibling;
  if (const char* env = std::getenv("BRDFKIT_DATA_DIR"); env && *env) {
    if (const auto dir = std::filesystem::path(env) / "cie"; holds_tables(dir)) return dir;
  }
  std::string list;
  for (const auto& p : tried) list += (list.empty() ? "" : ", ") + p.string();
  throw InputError(data_file.string(),
                   "spectral data need the CIE tables (cie1931-2deg-xyz-1nm.csv, cie-d65-5nm.csv); not found in " +
                       list + " (set BRDFKIT_CIE_DIR)");
}

const SpectrumToRgb& spectrum_to_rgb_for(const std::filesystem::path& data_file) {
  static std::mutex mutex;
  static std::map<std::filesystem::path, std::unique_ptr<SpectrumToRgb>> cache;
  const auto dir = std::filesystem::weakly_canonical(default_cie_dir(data_file));
  std::lock_guard lock(mutex);
  auto& slot = cache[dir];
  if (!slot) slot = std::make_unique<SpectrumToRgb>(dir);
  return *slot;
}

}  // namespace brdfkit
