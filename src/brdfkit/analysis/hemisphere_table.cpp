#include "brdfkit/analysis/hemisphere_table.h"

#include <algorithm>
#include <cmath>

#include <boost/math/quadrature/gauss.hpp>

#include "brdfkit/core/error.h"

namespace brdfkit::analysis {

namespace {
// 6 points per cell side: exact for the bilinear D times cosθ sinθ to far below the table's own
// error, and σ's kink along ω·m = 0 costs O(cell²) of one cell.
using Rule = boost::math::quadrature::gauss<double, 6>;
constexpr int kAreaThetaSteps = 45;  // σ grid: 2° steps, 0° … 90°

// Abscissae and weights of Rule on [0, 1].
std::vector<std::pair<double, double>> unit_rule() {
  std::vector<std::pair<double, double>> out;
  const auto& xs = Rule::abscissa();
  const auto& ws = Rule::weights();
  for (size_t i = 0; i < xs.size(); ++i) {
    out.emplace_back(0.5 + 0.5 * xs[i], 0.5 * ws[i]);
    if (xs[i] != 0.0) out.emplace_back(0.5 - 0.5 * xs[i], 0.5 * ws[i]);
  }
  return out;
}
}  // namespace

HemisphereTable::HemisphereTable(int n_theta, int n_phi) : n_theta_(n_theta), n_phi_(n_phi) {
  if (n_theta < 3 || n_phi < 4) throw InputError("hemisphere table", "needs at least 3 rings and 4 azimuths");
  for (int j = 0; j < n_theta; ++j) {
    const double u = double(j) / (n_theta - 1);
    theta_.push_back(u * u * kPi / 2);
  }
  mass_weight_.assign(size_t(nodes()), 0.0);
  const auto rule = unit_rule();
  const double dphi = 2 * kPi / n_phi;
  for (int j = 0; j + 1 < n_theta; ++j)
    for (int k = 0; k < n_phi; ++k)
      for (const auto& [a, wa] : rule)
        for (const auto& [b, wb] : rule) {
          const double th = theta_[size_t(j)] + a * (theta_[size_t(j) + 1] - theta_[size_t(j)]);
          const Vec3d m = spherical_direction(th, (k + b) * dphi);
          const double w = wa * wb * (theta_[size_t(j) + 1] - theta_[size_t(j)]) * dphi * std::sin(th);
          const Stencil s = locate(m);
          points_.push_back({m, s, w});
          for (int q = 0; q < s.count; ++q) mass_weight_[size_t(s.node[size_t(q)])] += s.weight[size_t(q)] * w * m.z();
        }
}

int HemisphereTable::node(int j, int k) const {
  if (j == 0) return 0;
  const int kk = ((k % n_phi_) + n_phi_) % n_phi_;
  return 1 + (j - 1) * n_phi_ + kk;
}

double HemisphereTable::phi(int k) const { return 2 * kPi * k / n_phi_; }

HemisphereTable::Stencil HemisphereTable::locate(const Vec3d& h) const {
  // Elevation from the chord to the pole: accurate near the normal, where acos(z) is not.
  const double chord = std::sqrt(h.x() * h.x() + h.y() * h.y() + (h.z() - 1) * (h.z() - 1));
  const double th = std::clamp(2 * std::asin(std::min(1.0, 0.5 * chord)), 0.0, kPi / 2);
  // θ_j = (j/(nθ−1))² π/2 inverts to j = (nθ−1) sqrt(2θ/π).
  const double uj = (n_theta_ - 1) * std::sqrt(th * 2 / kPi);
  const int j = std::clamp(int(uj), 0, n_theta_ - 2);
  const double t = std::clamp((th - theta_[size_t(j)]) / (theta_[size_t(j) + 1] - theta_[size_t(j)]), 0.0, 1.0);
  double az = std::atan2(h.y(), h.x()) / (2 * kPi) * n_phi_;
  if (az < 0) az += n_phi_;
  const int k = std::min(int(az), n_phi_ - 1);
  const double f = std::clamp(az - k, 0.0, 1.0);
  Stencil s;
  auto add = [&](int n, double w) {
    s.node[size_t(s.count)] = n;
    s.weight[size_t(s.count)] = w;
    ++s.count;
  };
  if (j == 0) {
    add(0, 1 - t);
  } else {
    add(node(j, k), (1 - t) * (1 - f));
    add(node(j, k + 1), (1 - t) * f);
  }
  add(node(j + 1, k), t * (1 - f));
  add(node(j + 1, k + 1), t * f);
  return s;
}

double HemisphereTable::eval(const std::vector<double>& d, const Vec3d& h) const {
  return h.z() > 0 ? locate(h).apply(d) : 0.0;
}

double HemisphereTable::mass(const std::vector<double>& d) const {
  double sum = 0;
  for (size_t n = 0; n < d.size(); ++n) sum += mass_weight_[n] * d[n];
  return sum;
}

std::vector<std::array<int, 3>> HemisphereTable::second_differences() const {
  std::vector<std::array<int, 3>> out;
  for (int k = 0; k < n_phi_; ++k)
    for (int j = 1; j + 1 < n_theta_; ++j) out.push_back({node(j - 1, k), node(j, k), node(j + 1, k)});
  for (int j = 1; j < n_theta_; ++j)
    for (int k = 0; k < n_phi_; ++k) out.push_back({node(j, k - 1), node(j, k), node(j, k + 1)});
  return out;
}

HemisphereTable::Masking HemisphereTable::masking(const std::vector<double>& d) const {
  std::vector<double> dm(points_.size());
  for (size_t p = 0; p < points_.size(); ++p) dm[p] = points_[p].stencil.apply(d) * points_[p].weight;
  Masking out;
  out.n_theta = kAreaThetaSteps + 1;
  out.n_phi = n_phi_;
  out.area.resize(size_t(out.n_theta) * size_t(out.n_phi));
  for (int a = 0; a < out.n_theta; ++a)
    for (int b = 0; b < out.n_phi; ++b) {
      const Vec3d w = spherical_direction(a * kPi / 2 / kAreaThetaSteps, phi(b));
      double sigma = 0;
      for (size_t p = 0; p < points_.size(); ++p) sigma += std::max(0.0, w.dot(points_[p].m)) * dm[p];
      out.area[size_t(a) * size_t(out.n_phi) + size_t(b)] = sigma;
    }
  return out;
}

double HemisphereTable::Masking::projected_area(const Vec3d& w) const {
  const double th = std::acos(std::clamp(w.z(), 0.0, 1.0));
  const double x = th / (kPi / 2) * (n_theta - 1);
  const int a = std::clamp(int(x), 0, n_theta - 2);
  const double t = std::clamp(x - a, 0.0, 1.0);
  double az = std::atan2(w.y(), w.x()) / (2 * kPi) * n_phi;
  if (az < 0) az += n_phi;
  const int b = std::min(int(az), n_phi - 1), b1 = (b + 1) % n_phi;
  const double f = std::clamp(az - b, 0.0, 1.0);
  auto at = [&](int i, int k) { return area[size_t(i) * size_t(n_phi) + size_t(k)]; };
  return (1 - t) * ((1 - f) * at(a, b) + f * at(a, b1)) + t * ((1 - f) * at(a + 1, b) + f * at(a + 1, b1));
}

double HemisphereTable::Masking::g1(const Vec3d& w) const {
  const double c = w.z();
  if (!(c > 0)) return 0.0;
  return c / std::max(c, projected_area(w));
}

}  // namespace brdfkit::analysis
