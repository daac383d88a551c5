#include "brdfkit/measured/diffraction_map.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <string>

#include "brdfkit/core/error.h"
#include "brdfkit/core/half_diff.h"

namespace brdfkit {

namespace {

void check(const DiffractionOptions& opt) {
  if (opt.theta_h_cells < 3 || opt.theta_d_cells < 3 || opt.phi_d_samples < 1 || opt.theta_h_cells > 1000 ||
      opt.theta_d_cells > 1000 || opt.phi_d_samples > 1000)
    throw InputError("diffraction map", "grid sizes must be in [3, 1000] (phi_d in [1, 1000])");
  if (!(opt.threshold > 0)) throw SettingError("threshold", "must be > 0");
  if (!(opt.max_theta > 0 && opt.max_theta <= kPi / 2)) throw InputError("diffraction map", "max_theta must be in (0, pi/2]");
}

// Each cell's mean and variance of ρ over φd, from the pairs with θi, θo < max_theta.
void average_over_phi_d(const MeasuredBrdf& data, const DiffractionOptions& opt, DiffractionMap& map) {
  const int nh = opt.theta_h_cells, nd = opt.theta_d_cells, np = opt.phi_d_samples;
  const double cos_max = std::cos(opt.max_theta);
  tbb::parallel_for(0, nh, [&](int i) {
    const double u = (i + 0.5) / nh;
    for (int j = 0; j < nd; ++j) {
      DiffractionCell& cell = map.cells[size_t(i) * size_t(nd) + size_t(j)];
      cell.theta_h = u * u * kPi / 2;
      cell.theta_d = (j + 0.5) / nd * kPi / 2;
      Rgb sum = Rgb::Zero(), sum2 = Rgb::Zero();
      for (int k = 0; k < np; ++k) {
        Vec3d wi, wo;
        from_half_diff({cell.theta_h, 0.0, cell.theta_d, (k + 0.5) / np * kPi}, wi, wo);
        if (!(wi.z() > cos_max && wo.z() > cos_max)) continue;
        const auto m = data.eval(wi, wo);
        if (!m || !m->allFinite()) continue;
        sum += *m;
        sum2 += *m * *m;
        ++cell.count;
      }
      if (cell.count > 0) {
        cell.mean = sum / cell.count;
        cell.variance = (sum2 / cell.count - cell.mean * cell.mean).max(0.0);
      }
    }
  });
}

// det(∇ log ρ, ∇f) of channel c in every cell where it can be formed, and the classification.
void classify(DiffractionMap& map, int c) {
  const int nh = map.theta_h_cells, nd = map.theta_d_cells;
  auto at = [&](int i, int j) -> const DiffractionCell& { return map.cells[size_t(i) * size_t(nd) + size_t(j)]; };
  auto log_rho = [&](int i, int j, double& out) {
    const DiffractionCell& x = at(i, j);
    if (x.count == 0 || !(x.mean[c] > 0)) return false;
    out = std::log(x.mean[c]);
    return true;
  };
  // d log ρ along one axis: central difference where both neighbours answer, one-sided otherwise.
  auto derivative = [&](int i, int j, int di, int dj, double& out) {
    double l0, lm, lp;
    if (!log_rho(i, j, l0)) return false;
    const int im = i - di, jm = j - dj, ip = i + di, jp = j + dj;
    const bool has_m = im >= 0 && jm >= 0 && log_rho(im, jm, lm);
    const bool has_p = ip < nh && jp < nd && log_rho(ip, jp, lp);
    auto angle = [&](int a, int b) { return di ? at(a, b).theta_h : at(a, b).theta_d; };
    if (has_m && has_p) out = (lp - lm) / (angle(ip, jp) - angle(im, jm));
    else if (has_p) out = (lp - l0) / (angle(ip, jp) - angle(i, j));
    else if (has_m) out = (l0 - lm) / (angle(i, j) - angle(im, jm));
    else return false;
    return true;
  };
  const size_t ch = size_t(c);
  const double k2l = 2.0 / kChannelWavelengthUm[c];  // f = (2/λ) sinθh cosθd (seed 004 Eq. 11, DESIGN.md §6)
  for (int i = 0; i < nh; ++i)
    for (int j = 0; j < nd; ++j) {
      DiffractionCell& cell = map.cells[size_t(i) * size_t(nd) + size_t(j)];
      double dh, dd;
      if (!derivative(i, j, 1, 0, dh) || !derivative(i, j, 0, 1, dd)) continue;
      const double fh = k2l * std::cos(cell.theta_h) * std::cos(cell.theta_d);
      const double fd = -k2l * std::sin(cell.theta_h) * std::sin(cell.theta_d);
      cell.det[ch] = dh * fd - dd * fh;  // seed 004 Eq. 15
      cell.has_det[ch] = true;
      cell.diffraction[ch] = std::abs(cell.det[ch]) < map.threshold;
      ++map.classified[ch];
      map.diffraction_cells[ch] += cell.diffraction[ch];
    }
  map.diffraction_fraction[ch] = map.classified[ch] > 0 ? double(map.diffraction_cells[ch]) / map.classified[ch] : 0.0;
}

}  // namespace

DiffractionMap diffraction_map(const MeasuredBrdf& data, const DiffractionOptions& opt) {
  check(opt);
  DiffractionMap map;
  map.theta_h_cells = opt.theta_h_cells;
  map.theta_d_cells = opt.theta_d_cells;
  map.threshold = opt.threshold;
  map.cells.resize(size_t(opt.theta_h_cells) * size_t(opt.theta_d_cells));
  average_over_phi_d(data, opt, map);
  int with_data = 0;
  for (const auto& c : map.cells) with_data += c.count > 0;
  if (with_data == 0)
    throw InputError(data.path(), "no value on the (theta_h, theta_d) grid: the diffraction test needs data that "
                                  "answer rho(wi, wo) (tables, not scattered samples or slices)");
  for (int c = 0; c < 3; ++c) classify(map, c);
  return map;
}

}  // namespace brdfkit
