#include "brdfkit/analysis/projected_area_masking.h"

#include <algorithm>
#include <cmath>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "brdfkit/core/vec.h"

namespace brdfkit::analysis {

namespace {

// ∫₀^{2π} max(0, a + b cos φ) dφ with b ≥ 0: the azimuthal part of ⟨ω·m⟩ for ω at θ and m at θm
// (a = cosθ cosθm, b = sinθ sinθm); the positive part spans |φ| < acos(−a/b).
double azimuthal_clamped_cosine(double a, double b) {
  if (a >= b) return 2 * kPi * a;
  if (a <= -b) return 0.0;
  const double phi_c = std::acos(std::clamp(-a / b, -1.0, 1.0));
  return 2 * (a * phi_c + b * std::sin(phi_c));
}

}  // namespace

ProjectedAreaMasking::ProjectedAreaMasking(const std::function<double(double)>& d, const std::vector<double>& kinks,
                                           int nodes) {
  area_.assign(std::size_t(std::max(nodes, 2)), 1.0);
  const int n = int(area_.size());
  for (int k = 0; k < n; ++k) {
    const double theta = double(k) / (n - 1) * (kPi / 2);
    const double ct = k + 1 == n ? 0.0 : std::cos(theta), st = std::sin(theta);
    // Panels between kinks of D and the angle π/2 − θ where the clamp starts to bite.
    std::vector<double> cuts = {0.0, kPi / 2};
    for (double t : kinks)
      if (t > 0 && t < kPi / 2) cuts.push_back(t);
    if (theta > 0) cuts.push_back(kPi / 2 - theta);
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end(), [](double a, double b) { return b - a < 1e-12; }), cuts.end());
    double sum = 0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      auto f = [&](double tm) {
        const double cm = std::cos(tm), sm = std::sin(tm);
        return d(cm) * azimuthal_clamped_cosine(ct * cm, st * sm) * sm;
      };
      sum += boost::math::quadrature::gauss_kronrod<double, 15>::integrate(f, cuts[i], cuts[i + 1], 0);
    }
    area_[std::size_t(k)] = sum;
  }
}

double ProjectedAreaMasking::g1(double cos_theta) const {
  if (!(cos_theta > 0)) return 0.0;
  const double theta = std::acos(std::min(1.0, cos_theta));
  const int n = int(area_.size());
  const double x = theta / (kPi / 2) * (n - 1);
  const int i = std::clamp(int(x), 0, n - 2);
  const double w = x - i;
  const double area = (1 - w) * area_[std::size_t(i)] + w * area_[std::size_t(i + 1)];
  return cos_theta / std::max(cos_theta, area);  // A ≥ cosθ, i.e. Λ ≥ 0 (Heitz 2014 Eq. 2)
}

double ProjectedAreaMasking::lambda(double cos_theta) const {
  const double g = g1(cos_theta);
  return g > 0 ? 1.0 / g - 1.0 : 1e300;
}

}  // namespace brdfkit::analysis
