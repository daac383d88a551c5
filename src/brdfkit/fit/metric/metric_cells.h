#pragma once
// The sample domain of a metric on a MERL table: the table's own cells. A cell's value
// is exact at its centre (measured/merl_tabulate.h fills cells there, and a real measurement is
// binned there), whereas a (θi, θo, Δφ) grid looked up in the nearest cell compares the model at
// the grid point with the value at another point: a bias of ~0.7 % in a fitted Beckmann α.
//
// Each metric keeps its paper's integral and changes only the quadrature: a metric of DESIGN.md §7
// is ∫∫ (T(f ρ) − T(f m))² μ(wi, wo) dωi dωo over its domain, and a cell contributes its centre's
// residual times μ at the centre times the cell's pair measure ∫ dωi dωo (merl_cell_weight).
// A cell stands for both orientations (wi, wo) and (wo, wi) (φd and φd + π share it by
// reciprocity), each with half of its measure.
#include <vector>

#include "brdfkit/fit/metric/metric_grid.h"
#include "brdfkit/measured/merl.h"

namespace brdfkit::fit {

struct CellWeighting {
  // μ(wi, wo): the metric's weight per unit pair measure dωi dωo at one orientation of a cell
  // centre; 0 outside the metric's domain.
  double (*density)(const Vec3d& wi, const Vec3d& wo) = nullptr;
  bool cos_i_factor = false;  // the residual compares cosθi·ρ (f = cosθi of the orientation)
  // Both orientations in one sample, weight ½ μ(wi,wo) f(wi)² + ½ μ(wo,wi) f(wo)² and f = 1:
  // exact for a residual linear in ρ and a reciprocal model. Otherwise two samples per cell.
  bool fold = true;
};

struct CellDomain {
  std::vector<MetricChunk> chunks;
  double measure_sum = 0;  // Σ pair measure of the cells in the domain (ngan's Σ w)
};

// The domain's chunks, one at a time (for a metric only reported, whose domain is not kept):
// their number at a coarsening, and chunk i built into `out` (its arrays' capacity reused),
// returning the chunk's Σ pair measure.
size_t cell_chunk_count(int coarsen);
double build_cell_chunk(const merl::Table& table, const CellWeighting& weighting, int coarsen, size_t i,
                        MetricChunk& out);

// The valid cells of `table` whose centre lies in the domain (μ > 0 for either orientation), in
// file order, cut into chunks of at most 15 θd rows of one θh row. coarsen k > 1 keeps one cell
// of each k × k × k block of indices (its middle one, when valid) with the block's measure.
CellDomain build_cell_domain(const merl::Table& table, const CellWeighting& weighting, int coarsen);

}  // namespace brdfkit::fit
