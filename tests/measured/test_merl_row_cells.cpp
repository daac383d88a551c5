// merl::row_cells must give cell_of's cell (MERL's rotations) for every pair, including pairs
// whose angles sit on a cell boundary, where the rounding of its own angles would otherwise
// move the floor: on random pairs, on the rows of an albedo grid, and on pairs built at the
// boundaries themselves (θd and φd on multiples of the cell width, φd = 0 and π, wi = wo, h = n).
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "brdfkit/core/half_diff.h"
#include "brdfkit/measured/merl.h"
#include "brdfkit/measured/merl_row_cells.h"

namespace brdfkit::merl {
namespace {

// Pairs compared and pairs above the horizon.
struct Count {
  int compared = 0, above = 0;
};

void expect_cell_of(const Vec3d& wi, const std::vector<Vec3d>& wo, Count& count) {
  std::vector<size_t> cells;
  row_cells(wi, wo, cells);
  ASSERT_EQ(cells.size(), wo.size());
  for (size_t k = 0; k < wo.size(); ++k, ++count.compared) {
    if (!(wi.z() > 0 && wo[k].z() > 0)) {
      ASSERT_EQ(cells[k], kNoCell) << "pair " << k;
      continue;
    }
    ++count.above;
    ASSERT_EQ(cells[k], cell_offset(cell_of(wi, wo[k])))
        << "wi (" << wi.transpose() << ") wo (" << wo[k].transpose() << ")";
  }
}

TEST(MerlRowCells, RandomPairsGetCellOfsCells) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Count count;
  for (int row = 0; row < 200; ++row) {
    const Vec3d wi = spherical_direction(1.6 * u(rng), 2 * kPi * u(rng));
    std::vector<Vec3d> wo;
    for (int k = 0; k < 700; ++k) wo.push_back(spherical_direction(1.65 * u(rng), 2 * kPi * u(rng)));
    expect_cell_of(wi, wo, count);
  }
  EXPECT_EQ(count.compared, 200 * 700);
  EXPECT_GT(count.above, count.compared * 9 / 10);
}

TEST(MerlRowCells, AlbedoGridRowsGetCellOfsCells) {
  Count count;
  const double deg = kPi / 180;
  for (int i = 0; i < 80; i += 3) {
    const Vec3d wi = spherical_direction((i + 0.5) * deg, 0.0);
    std::vector<Vec3d> wo;
    for (int o = 0; o < 90; ++o)
      for (int p = 0; p < 360; ++p) wo.push_back(spherical_direction((o + 0.5) * deg, (p + 0.5) * deg));
    expect_cell_of(wi, wo, count);
  }
  EXPECT_EQ(count.above, 27 * 90 * 360);
}

TEST(MerlRowCells, PairsOnCellBoundariesGetCellOfsCells) {
  Count count;
  auto boundary_pairs = [&](double theta_h, double phi_h) {
    std::vector<double> theta_d = {3e-8, 1e-7, 1e-6};  // φd ill-conditioned
    for (int j = 0; j <= kResThetaD; ++j) theta_d.push_back(j * (kPi / 2) / kResThetaD);
    for (double td : theta_d)
      for (int k = 0; k <= 2 * kResPhiD; k += 5) {
        Vec3d wi, wo;
        from_half_diff({theta_h, phi_h, td, k * kPi / kResPhiD}, wi, wo);
        expect_cell_of(wi, {wo}, count);
      }
  };
  for (int i = 0; i < kResThetaH; i += 7) {
    const double u = double(i) / kResThetaH;
    boundary_pairs(u * u * (kPi / 2), 0.0);  // θh on its own boundary too
    boundary_pairs(u * u * (kPi / 2), 0.7);
  }
  for (const Vec3d& w : {Vec3d(0, 0, 1), spherical_direction(0.4, 1.0), spherical_direction(1.2, -2.0)}) {
    expect_cell_of(w, {w}, count);                          // wi = wo: θd = 0, φd undefined
    expect_cell_of(w, {Vec3d(-w.x(), -w.y(), w.z())}, count);  // h = n: θh = 0, φh undefined
  }
  EXPECT_GT(count.above, 10000);
}

}  // namespace
}  // namespace brdfkit::merl
