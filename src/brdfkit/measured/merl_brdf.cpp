#include "brdfkit/measured/merl_brdf.h"

#include <cmath>

namespace brdfkit {

double merl_cell_weight(const merl::Cell& c) {
  using namespace merl;
  auto theta_h = [](int i) {
    const double u = double(i) / kResThetaH;
    return u * u * (kPi / 2);  // θh axis of DESIGN.md §2, at the cell's lower and upper edges
  };
  auto sin2_theta_d = [](int j) {
    const double s = std::sin(double(j) / kResThetaD * (kPi / 2));
    return s * s;
  };
  const double d_cos_h = std::cos(theta_h(c.theta_h)) - std::cos(theta_h(c.theta_h + 1));
  const double d_sin2_d = sin2_theta_d(c.theta_d + 1) - sin2_theta_d(c.theta_d);
  return 2 * kPi * d_cos_h * 4 * 0.5 * d_sin2_d * 2 * (kPi / kResPhiD);
}

SampleSet MerlBrdf::samples() const {
  SampleSet s;
  s.reserve(table_.valid_count());
  for (size_t k = 0; k < merl::kCellCount; ++k) {
    if (!table_.valid(k)) continue;
    const merl::Cell c = merl::cell_at(k);
    Vec3d wi, wo;
    if (!merl::cell_directions(c, wi, wo)) continue;
    s.push_back(wi, wo, table_.value(k), merl_cell_weight(c), true);
  }
  return s;
}

std::unique_ptr<MerlBrdf> read_merl(const std::filesystem::path& file) {
  return std::make_unique<MerlBrdf>(merl::read(file), file.string());
}

}  // namespace brdfkit
