#pragma once
// Tabulating any BRDF into the MERL format (DESIGN.md §2): every cell is filled BY INDEX at its
// centre (merl::cell_centre), never through the look-up, so the table round-trips through the
// reference floor rule; cells whose centre directions are at or below the horizon are written as
// raw −1 (not measured), as real MERL files do.
#include <functional>

#include "brdfkit/measured/merl.h"

namespace brdfkit::merl {

// ρ(wi, wo) in sr⁻¹ per channel.
using TabulatedBrdf = std::function<Rgb(const Vec3d& wi, const Vec3d& wo)>;

// Parallel over θh rows (TBB); each cell is written by exactly one task, so the result does not
// depend on the schedule. Throws InputError if rho returns a non-finite value (naming the cell);
// negative values are stored as they are and so become "not measured" cells.
Table tabulate(const TabulatedBrdf& rho);

}  // namespace brdfkit::merl
