#include "brdfkit/measured/cornell.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <span>
#include <sstream>

#include <fmt/format.h>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/spectral_rgb.h"
#include "brdfkit/measured/text_numbers.h"
#include "brdfkit/measured/value_limit.h"

namespace brdfkit {

namespace {

// Ring index k of 1 − cos θs = (k/10)² (DESIGN.md §2), nearest ring.
int ring_of(double theta_s) { return int(std::lround(10 * std::sqrt(std::max(0.0, 1 - std::cos(theta_s))))); }

// A Cornell file is refused, not patched, when a spectral value cannot be a measurement (beyond
// ±kMaxMeasuredValue; non-finite tokens are refused by parse_numbers): the format has no "not
// measured" mark (a direction not measured is a line not written), so such a value is corruption,
// and dropping its sample would hide it while shifting the solid-angle weights of its ring.
void check_spectral_values(std::span<const double> values, const std::vector<double>& wavelengths, const std::string& where) {
  for (size_t j = 0; j < values.size(); ++j)
    if (std::abs(values[j]) > kMaxMeasuredValue)
      throw InputError(where, fmt::format("spectral value {} ({} nm) is {}: beyond ±{} sr⁻¹, not a measurement", j,
                                          wavelengths[j], values[j], kMaxMeasuredValue));
}

// What a Cornell text file holds: the header's wavelengths, then per sample line θi φi θs φs and
// the spectral values.
struct CornellText {
  std::vector<double> wavelengths;
  std::vector<std::array<double, 4>> angles;
  std::vector<std::vector<double>> spectra;
};

// Parses and checks every line; InputError naming the file and line.
CornellText read_text(std::istream& in, const std::string& path) {
  CornellText t;
  std::string line;
  int line_no = 0;
  size_t n_wl = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();  // CRLF files
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::string where = fmt::format("{}:{}", path, line_no);
    const std::vector<double> v = parse_numbers(line, where);
    if (n_wl == 0) {  // header: the wavelength count
      if (v.size() != 1 || v[0] < 1 || v[0] > 10000 || v[0] != std::floor(v[0]))
        throw InputError(where, "expected the wavelength count (one positive integer)");
      n_wl = size_t(v[0]);
      continue;
    }
    if (t.wavelengths.size() < n_wl) {  // header: the wavelengths, over one or more lines
      t.wavelengths.insert(t.wavelengths.end(), v.begin(), v.end());
      if (t.wavelengths.size() > n_wl)
        throw InputError(where, fmt::format("more wavelengths than the {} announced", n_wl));
      continue;
    }
    if (v.size() != 4 + n_wl)
      throw InputError(where, fmt::format("sample line has {} values, expected {} (θi φi θs φs and {} spectral values)", v.size(),
                                          4 + n_wl, n_wl));
    if (v[0] < 0 || v[0] >= kPi / 2 || v[2] < 0 || v[2] >= kPi / 2)
      throw InputError(where, fmt::format("angles out of range: θi = {}, θs = {} (radians, in [0, π/2))", v[0], v[2]));
    check_spectral_values(std::span(v).subspan(4), t.wavelengths, where);
    t.angles.push_back({v[0], v[1], v[2], v[3]});
    t.spectra.emplace_back(v.begin() + 4, v.end());
  }
  if (n_wl == 0) throw InputError(path, "no wavelength count found (empty file?)");
  if (t.wavelengths.size() < n_wl) throw InputError(path, fmt::format("only {} of the {} wavelengths", t.wavelengths.size(), n_wl));
  for (size_t j = 1; j < n_wl; ++j)
    if (!(t.wavelengths[j] > t.wavelengths[j - 1])) throw InputError(path, "wavelengths must increase");
  if (t.spectra.empty()) throw InputError(path, "no samples");
  return t;
}

// Solid-angle weights (see the header): samples per (θi, ring), then band area / count.
std::vector<double> solid_angle_weights(const std::vector<std::array<double, 4>>& angles) {
  std::map<std::pair<long, int>, int> per_ring;
  auto key = [](const std::array<double, 4>& a) { return std::pair{std::lround(a[0] * 1e5), ring_of(a[2])}; };
  for (const auto& a : angles) ++per_ring[key(a)];
  auto band_edge = [](int k) { return k <= 0 ? 0.0 : k >= 10 ? 1.0 : std::pow((k - 0.5) / 10, 2); };
  std::vector<double> w;
  w.reserve(angles.size());
  for (const auto& a : angles) {
    const int ring = std::min(ring_of(a[2]), 9);
    w.push_back(2 * kPi * (band_edge(ring + 1) - band_edge(ring)) / per_ring[key(a)]);
  }
  return w;
}

}  // namespace

CornellBrdf::CornellBrdf(const std::filesystem::path& file, const std::filesystem::path& cie_dir) : path_(file.string()) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(path_, "cannot open file");
  CornellText text = read_text(in, path_);
  wavelengths_ = std::move(text.wavelengths);
  spectra_ = std::move(text.spectra);

  std::unique_ptr<SpectrumToRgb> own;
  if (!cie_dir.empty()) own = std::make_unique<SpectrumToRgb>(cie_dir);
  const SpectrumToRgb& conv = own ? *own : default_spectrum_to_rgb();
  const Eigen::MatrixXd m = conv.matrix(wavelengths_);
  const std::vector<double> weights = solid_angle_weights(text.angles);
  samples_.reserve(text.angles.size());
  for (size_t k = 0; k < text.angles.size(); ++k) {
    const auto& a = text.angles[k];
    const Eigen::Vector3d rgb = m * Eigen::Map<const Eigen::VectorXd>(spectra_[k].data(), Eigen::Index(wavelengths_.size()));
    samples_.push_back(spherical_direction(a[0], a[1]), spherical_direction(a[2], a[3]), rgb.array(), weights[k], true);
  }
}

std::string CornellBrdf::dimensions() const {
  return fmt::format("{} scattered samples, {} wavelengths {}-{} nm, {} incidence angles", samples_.size(), wavelengths_.size(),
                     wavelengths_.front(), wavelengths_.back(), theta_i_values().size());
}

SampleSet CornellBrdf::samples() const { return samples_; }

std::vector<double> CornellBrdf::theta_i_values() const {
  std::vector<double> t;
  for (size_t k = 0; k < samples_.size(); ++k) t.push_back(theta_of(samples_.wi(k)));
  std::sort(t.begin(), t.end());
  std::vector<double> out;
  for (double x : t)
    if (out.empty() || x - out.back() > 1e-5) out.push_back(x);
  return out;
}

Rgb CornellBrdf::directional_albedo_from_samples(double theta_i) const {
  Rgb a = Rgb::Zero();
  bool any = false;
  for (size_t k = 0; k < samples_.size(); ++k) {
    if (std::abs(theta_of(samples_.wi(k)) - theta_i) > 1e-5) continue;
    a += samples_.value(k) * samples_.wo_z[k] * samples_.weight[k];
    any = true;
  }
  if (!any) throw InputError(path_, fmt::format("no samples at θi = {} rad", theta_i));
  return a;
}

std::vector<std::pair<double, Rgb>> CornellBrdf::albedos_from_samples() const {
  std::vector<std::pair<double, Rgb>> out;
  for (double t : theta_i_values()) out.emplace_back(t, directional_albedo_from_samples(t));
  return out;
}

std::unique_ptr<MeasuredBrdf> read_cornell(const std::filesystem::path& file) { return std::make_unique<CornellBrdf>(file); }

}  // namespace brdfkit
