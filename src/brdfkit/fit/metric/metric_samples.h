#pragma once
// The sample domain of a metric on scattered measurements: data that answer no lookup
// at an arbitrary direction pair (Cornell files, ALTA slices) are compared with the model at their
// own samples instead of a grid.
//
// As on MERL cells (metric_cells.h), each metric keeps its paper's integral
// ∫∫ (T(f ρ) − T(f m))² μ(wi, wo) dωi dωo and changes only the quadrature: a sample contributes
// its residual times μ at its pair times its pair measure. The pair measure is the reader's own
// weight (SampleSet::weight) where that is already a pair measure, and otherwise the reader's
// outgoing solid angle times an incidence solid angle (see below).
//
// Pair measure. Readers give weight = the solid angle of wo the sample stands for, conditioned on
// its θi (measured/cornell.h: the samples of one θi sum to 2π). The incidence directions of such
// files are a few θi rings, each then standing for the band of cos θi between the midpoints to its
// neighbours (0 and 90° at the ends): 2π·(cos θ_lo − cos θ_hi). The pair measures then sum to
// 4π² like ∫∫ dωi dωo. A set with one sample per θi (an ALTA slice wi = wo: a curve, not a 4D
// set) carries its whole measure in its weight (2π Δcos θh) and takes no incidence factor.
// Samples are never folded (unlike MERL cells): each is its own orientation, with f = cos θi of
// its own wi, so the domain is exact for non-reciprocal models too.
#include <vector>

#include "brdfkit/fit/metric/metric_grid.h"
#include "brdfkit/measured/measured_brdf.h"

namespace brdfkit::fit {

struct SampleDomain {
  std::vector<MetricChunk> chunks;
  double measure_sum = 0;  // Σ pair measure of the samples in the domain (ngan's Σ w)
};

// Whether `data` are scattered samples: it holds samples, and eval() answers none of a few fixed
// direction pairs off the mirror line (a table answers nearly all of them).
bool is_scattered(const MeasuredBrdf& data);

// The valid samples with finite values, both directions above the horizon, positive weight and
// μ > 0, in file order, in chunks of at most 4096 samples. `density` is μ(wi, wo) per unit pair
// measure (0 outside the metric's domain); `cos_i_factor`: the residual compares cos θi · ρ.
SampleDomain build_sample_domain(const SampleSet& samples, double (*density)(const Vec3d& wi, const Vec3d& wo),
                                 bool cos_i_factor);

}  // namespace brdfkit::fit
