// Tabulating into the MERL format (DESIGN.md §2, measured/merl_tabulate.h) evaluates ρ(wi, wo)
// with wi the direction whose azimuth in the frame of h is φd (Rusinkiewicz 1998; MERL's
// std_coords_to_half_diff_coords rotates wi). A non-reciprocal function of θi alone shows which
// direction the writer passes first. `brdfkit tabulate` only takes catalogue models, which are
// all reciprocal, so this runs on the library's writer, which the command calls.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "brdfkit/measured/merl.h"
#include "brdfkit/measured/merl_tabulate.h"

namespace brdfkit::test {
namespace {

// MERL's half/difference angles back to the two directions (the inverse of
// std_coords_to_half_diff_coords): the difference vector d = (θd, φd) rotated about the binormal
// y by +θh, then about n by φh, is wi; wo is its mirror image about h.
void directions_of_cell(double theta_h, double theta_d, double phi_d, Vec3d& wi, Vec3d& wo) {
  const Vec3d d = spherical_direction(theta_d, phi_d);
  const Vec3d d_y(d.x() * std::cos(theta_h) + d.z() * std::sin(theta_h), d.y(),
                  d.z() * std::cos(theta_h) - d.x() * std::sin(theta_h));
  const double phi_h = 0.0;  // an isotropic table: any φh
  wi = Vec3d(d_y.x() * std::cos(phi_h) - d_y.y() * std::sin(phi_h),
             d_y.x() * std::sin(phi_h) + d_y.y() * std::cos(phi_h), d_y.z());
  const Vec3d h = spherical_direction(theta_h, phi_h);
  wo = 2 * wi.dot(h) * h - wi;
}

TEST(TabulateConvention, CellsHoldRhoOfTheirWiFirst) {
  // ρ = 1 + cosθi (wo ignored): a cell's value tells which of its directions came first.
  const merl::Table table = merl::tabulate([](const Vec3d& wi, const Vec3d&) { return Rgb(Rgb::Constant(1 + wi.z())); });
  int checked = 0, distinct = 0;
  for (int ih = 3; ih < 90; ih += 11)
    for (int id = 2; id < 90; id += 9)
      for (int ip = 5; ip < 180; ip += 23) {
        const size_t offset = size_t(ip) + 180 * (size_t(id) + 90 * size_t(ih));
        // Cell centres (DESIGN.md §2, ALTA's convention).
        const double th = std::pow((ih + 0.5) / 90, 2) * kPi / 2, td = (id + 0.5) / 90 * kPi / 2, pd = (ip + 0.5) / 180 * kPi;
        Vec3d wi, wo;
        directions_of_cell(th, td, pd, wi, wo);
        if (std::min(wi.z(), wo.z()) > -1e-9 && std::min(wi.z(), wo.z()) < 1e-9) continue;  // on the horizon
        if (!(wi.z() > 0 && wo.z() > 0)) {
          EXPECT_FALSE(table.valid(offset)) << ih << " " << id << " " << ip;
          continue;
        }
        ASSERT_TRUE(table.valid(offset)) << ih << " " << id << " " << ip;
        EXPECT_NEAR(table.value(offset)[1], 1 + wi.z(), 1e-12) << "cell " << ih << " " << id << " " << ip;
        if (std::abs(wi.z() - wo.z()) > 0.05) ++distinct;
        ++checked;
      }
  std::printf("[ convention ] tabulate: %d cells checked, %d where cos(theta_i) and cos(theta_o) differ by > 0.05\n",
              checked, distinct);
  EXPECT_GT(distinct, checked / 3);
}

}  // namespace
}  // namespace brdfkit::test
