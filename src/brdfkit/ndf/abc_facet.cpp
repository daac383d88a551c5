#include "brdfkit/ndf/abc_facet.h"

#include <boost/math/tools/roots.hpp>
#include <cstdint>

namespace brdfkit {

Vec3d abc_facet_sample(const AbcFacet<double>& d, const Vec2d& u) {
  const double L_max = std::log1p(d.B);
  const double target = u.x() * d.cos_weighted_mass_L(L_max);
  const double phi = 2 * kPi * u.y();
  double L;
  if (!(u.x() > 0.0)) {
    L = 0.0;
  } else if (!(u.x() < 1.0)) {
    L = L_max;
  } else {
    auto f = [&](double l) { return d.cos_weighted_mass_L(l) - target; };
    std::uintmax_t iters = 100;
    const auto [a, b] = boost::math::tools::toms748_solve(f, 0.0, L_max, -target, d.cos_weighted_mass_L(L_max) - target,
                                                          boost::math::tools::eps_tolerance<double>(50), iters);
    L = 0.5 * (a + b);
  }
  const double c = std::clamp(1.0 - std::expm1(L) / d.B, 0.0, 1.0);
  const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
  return Vec3d(s * std::cos(phi), s * std::sin(phi), c);
}

}  // namespace brdfkit
