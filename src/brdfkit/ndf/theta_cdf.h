#pragma once
// Sampling θ by inversion of a tabulated CDF, for the distributions whose CDF has no usable
// closed-form inverse (Gaussian, Sawicki rational, tabulated). The density per unit θ,
// f(θ) = 2π D(θ) cosθ sinθ, is sampled on a grid θᵢ = θmax (i/n)² that crowds near θ = 0,
// where narrow lobes live; f is taken piecewise linear between nodes, so the CDF is
// piecewise quadratic and is inverted exactly within a cell.
#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <vector>

#include "brdfkit/core/vec.h"

namespace brdfkit {

class ThetaCdf {
 public:
  ThetaCdf() = default;
  // density(θ) ≥ 0 on [0, theta_max], not necessarily normalized.
  template <class F> ThetaCdf(F&& density, double theta_max, int n = 8192) {
    theta_.resize(n + 1);
    f_.resize(n + 1);
    cdf_.resize(n + 1);
    for (int i = 0; i <= n; ++i) {
      const double t = double(i) / n;
      theta_[i] = theta_max * t * t;
      f_[i] = std::max(0.0, double(density(theta_[i])));
    }
    cdf_[0] = 0.0;
    for (int i = 0; i < n; ++i) cdf_[i + 1] = cdf_[i] + 0.5 * (f_[i] + f_[i + 1]) * (theta_[i + 1] - theta_[i]);
  }

  // Trapezoid integral of the density over [0, theta_max].
  double total() const { return cdf_.empty() ? 0.0 : cdf_.back(); }

  // θ with CDF(θ) = u·total, u ∈ [0, 1].
  double sample(double u) const {
    const double target = std::clamp(u, 0.0, 1.0) * total();
    auto it = std::upper_bound(cdf_.begin(), cdf_.end(), target);
    std::size_t i = std::clamp<std::size_t>(std::size_t(it - cdf_.begin()), 1, cdf_.size() - 1) - 1;
    const double h = theta_[i + 1] - theta_[i];
    const double r = std::max(0.0, target - cdf_[i]);
    const double f0 = f_[i], slope = (f_[i + 1] - f_[i]) / h;
    // f0 s + slope s²/2 = r, in the form that is stable for slope → 0 and for f0 = 0.
    const double disc = std::max(0.0, f0 * f0 + 2.0 * slope * r);
    const double denom = f0 + std::sqrt(disc);
    const double s = denom > 0.0 ? 2.0 * r / denom : 0.0;
    return theta_[i] + std::clamp(s, 0.0, h);
  }

 private:
  std::vector<double> theta_, f_, cdf_;
};

// The θ density 2π D(θ) cosθ sinθ of a distribution's normals on [0, theta_max].
template <class Ndf> ThetaCdf theta_cdf_of(const Ndf& ndf, double theta_max) {
  return ThetaCdf([&](double t) { return 2 * kPi * ndf.D(std::cos(t)) * std::cos(t) * std::sin(t); }, theta_max);
}

// A CDF built on first use and shared by copies of a distribution: fitting constructs many
// distributions that are never sampled, and sampling threads share one table.
struct LazyThetaCdf {
  std::once_flag once;
  ThetaCdf cdf;
  template <class Build> const ThetaCdf& get(Build&& build) {
    std::call_once(once, [&] { cdf = build(); });
    return cdf;
  }
};

// Unit vector at polar angle θ, with u ∈ [0, 1) for the azimuth: all distributions are isotropic.
inline Vec3d direction_from_theta(double theta, double u_phi) {
  const double phi = 2 * kPi * u_phi;
  const double s = std::sin(theta), c = std::cos(theta);
  return Vec3d(s * std::cos(phi), s * std::sin(phi), c);
}

}  // namespace brdfkit
