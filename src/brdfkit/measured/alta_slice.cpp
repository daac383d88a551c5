#include "brdfkit/measured/alta_slice.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <sstream>

#include <fmt/format.h>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/text_numbers.h"

namespace brdfkit {

AltaSlice::AltaSlice(const std::filesystem::path& file) : path_(file.string()) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(path_, "cannot open file");
  std::string line;
  int line_no = 0;
  bool dim = false, param_in = false, param_out = false;
  std::vector<std::pair<double, Rgb>> rows;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string where = fmt::format("{}:{}", path_, line_no);
    std::istringstream ss(line);
    std::string tok;
    if (!(ss >> tok)) continue;
    if (tok[0] == '#') {
      // ALTA header: `#DIM in out`, `#PARAM_IN name`, `#PARAM_OUT name`; other `#` lines are comments.
      std::string value;
      if (tok == "#DIM") {
        int n_in = 0, n_out = 0;
        if (!(ss >> n_in >> n_out) || n_in != 1 || n_out != 3)
          throw InputError(where, "expected '#DIM 1 3' (one input, RGB output): only θd = 0 slices are supported");
        dim = true;
      } else if (tok == "#PARAM_IN") {
        if (!(ss >> value) || value != "COS_TH") throw InputError(where, fmt::format("expected '#PARAM_IN COS_TH', found '{}'", value));
        param_in = true;
      } else if (tok == "#PARAM_OUT") {
        if (!(ss >> value) || value != "RGB_COLOR")
          throw InputError(where, fmt::format("expected '#PARAM_OUT RGB_COLOR', found '{}'", value));
        param_out = true;
      }
      continue;
    }
    if (!dim || !param_in || !param_out)
      throw InputError(where, "data before the ALTA header (#DIM 1 3, #PARAM_IN COS_TH, #PARAM_OUT RGB_COLOR)");
    const std::vector<double> v = parse_numbers(line, where);
    if (v.size() != 4) throw InputError(where, fmt::format("row has {} values, expected 4 (cos θh R G B)", v.size()));
    if (v[0] < 0 || v[0] > 1) throw InputError(where, fmt::format("cos θh = {} outside [0, 1]", v[0]));
    rows.emplace_back(v[0], Rgb(v[1], v[2], v[3]));
  }
  if (!dim || !param_in || !param_out) throw InputError(path_, "missing ALTA header (#DIM 1 3, #PARAM_IN COS_TH, #PARAM_OUT RGB_COLOR)");
  if (rows.empty()) throw InputError(path_, "no data rows");
  std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (size_t k = 1; k < rows.size(); ++k)
    if (rows[k].first == rows[k - 1].first) throw InputError(path_, fmt::format("duplicate cos θh = {}", rows[k].first));
  for (auto& [c, v] : rows) {
    cos_th_.push_back(c);
    rgb_.push_back(v);
  }
}

std::string AltaSlice::dimensions() const {
  return fmt::format("θd = 0 slice, {} rows, cos θh {:.4f}-{:.6f}", cos_th_.size(), cos_th_.front(), cos_th_.back());
}

std::optional<Rgb> AltaSlice::eval(const Vec3d& wi, const Vec3d& wo) const {
  if (!(wi.z() > 0) || (wi - wo).norm() > 1e-9) return std::nullopt;
  // On the slice θd = 0, h = wi, so cos θh = wi.z.
  const double c = wi.z();
  if (c <= cos_th_.front()) return rgb_.front();
  if (c >= cos_th_.back()) return rgb_.back();
  const size_t hi = size_t(std::upper_bound(cos_th_.begin(), cos_th_.end(), c) - cos_th_.begin());
  const size_t lo = hi - 1;
  const double t = (c - cos_th_[lo]) / (cos_th_[hi] - cos_th_[lo]);
  return Rgb((1 - t) * rgb_[lo] + t * rgb_[hi]);
}

SampleSet AltaSlice::samples() const {
  SampleSet s;
  const size_t n = cos_th_.size();
  s.reserve(n);
  for (size_t k = 0; k < n; ++k) {
    // Band of half-vector directions between the midpoints to the neighbouring rows (ends: the
    // end row itself, or cos θh = 1), solid angle 2π·Δcos θh.
    const double lo = k == 0 ? cos_th_[0] : 0.5 * (cos_th_[k - 1] + cos_th_[k]);
    const double hi = k + 1 == n ? 1.0 : 0.5 * (cos_th_[k] + cos_th_[k + 1]);
    const double theta = std::acos(cos_th_[k]);
    const Vec3d w = spherical_direction(theta, 0.0);
    s.push_back(w, w, rgb_[k], 2 * kPi * (hi - lo), cos_th_[k] > 0);
  }
  return s;
}

std::unique_ptr<MeasuredBrdf> read_alta_slice(const std::filesystem::path& file) { return std::make_unique<AltaSlice>(file); }

}  // namespace brdfkit
