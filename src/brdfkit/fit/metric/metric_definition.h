#pragma once
// What distinguishes the metrics of DESIGN.md §7: grid, transform, pooling and normalization.
// Each paper's metric lives in its own file (ngan_metric.cpp, bagher_metric.cpp, low_metric.cpp,
// hp_metric.cpp).
#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/fit/metric/metric_cells.h"
#include "brdfkit/fit/metric/metric_grid.h"
#include "brdfkit/fit/metric/metric_samples.h"

namespace brdfkit::fit {

struct MetricDefinition {
  GridSpec grid;
  Transform transform = Transform::Identity;
  bool sqrt = true;              // report √(Σ r²) (an RMS / L2 norm) rather than Σ r²
  double channel_pool = 1.0;     // multiplies Σ over channels: 1 = summed, 1/3 = averaged
  bool divide_by_weight_sum = false;  // Σ w over valid samples in the denominator (seed 002 Eq. 1)
  bool divide_by_max_albedo = false;  // reported relative to the max measured albedo (seed 002 §4.1)
  bool cache = true;             // keep the looked-up domain (false: rebuilt per evaluation)
  // The same integral on a MERL table's own cells (metric_cells.h), and its density μ(wi, wo) on
  // scattered samples (metric_samples.h, with the grid's cosθi factor); density nullptr: the
  // metric keeps its grid on both.
  CellWeighting cells;
};

MetricDefinition ngan_metric(int coarsen);
MetricDefinition bagher_metric(int coarsen);
MetricDefinition low_metric(int m, int coarsen);  // m = 1 (E1) or 2 (E2)
MetricDefinition hp_rmse_metric(int coarsen);

// Maximum over θi ∈ [0°, 80°] and channels of the measured directional albedo ∫ ρ cosθo dωo,
// integrated over the valid cells of a 1° (× coarsen) grid of the full outgoing hemisphere
// (DESIGN.md §7 "Choices"); from the data's own albedos where it supplies them (Cornell).
double max_measured_albedo(const MeasuredBrdf& data, int coarsen);

}  // namespace brdfkit::fit
