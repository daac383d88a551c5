#pragma once
// The MERL cells of many direction pairs that share one incidence (a row of a metric's grid, of an
// albedo integral), the same cells as cell_of(wi, wo) gives one pair at a time, in a fraction of
// its time.
//
// cell_of goes through MERL's rotations (to_half_diff: acos, two atan2, two sincos per pair). Here
// the half-vector frame comes from h's components (cos φh = hx/ρ, sin φh = hy/ρ, cos θh = hz,
// sin θh = ρ, ρ = |h_xy|) and the angles from glibc's vector acos and atan2, a block at a time.
// These angles differ from to_half_diff's by rounding only, which moves a cell boundary's floor
// only when an index coordinate lies within that rounding of an integer: such a pair, and one
// whose φd is ill-conditioned (θd near 0), is looked up through cell_of instead. So every cell
// is cell_of's (tests/measured/test_merl_row_cells.cpp).
#include <cstddef>
#include <span>
#include <vector>

#include "brdfkit/core/vec.h"

namespace brdfkit::merl {

// Offset (cell_offset) of the cell of each pair (wi, wo[k]), or kNoCell where either direction
// is at or below the horizon (where Table::lookup answers nullopt).
inline constexpr size_t kNoCell = ~size_t(0);
void row_cells(const Vec3d& wi, std::span<const Vec3d> wo, std::vector<size_t>& out);

}  // namespace brdfkit::merl
