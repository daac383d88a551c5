#pragma once
// Tabulated microfacet-distribution estimation from a measured BRDF (seed 002 §5.1, after
// Ashikhmin et al. 2000): with the masking fixed, ρ is linear in the table of D, so D (and the
// diffuse colour) are solved by linear least squares; then the masking is recomputed from the new
// D, and the two steps alternate (the paper starts from a constant masking and needs "about five
// or less iterations"). Fresnel is Schlick, with F0 given or fitted in an outer 1-D search (the
// paper's "optimization in the outermost loop"). The masking iterations are Anderson-accelerated
// (ndf_estimation.cpp): plain alternation converges linearly (≈ 0.57 per iteration on GGX α = 0.2).
//
// The least squares are those of a metric (fit/metric.h: the `ngan` metric by default), so the
// estimate minimizes the error that is reported for it. One D is shared by R, G, B (ks and kd
// are per channel): for fixed per-channel ks the problem is linear in (kd, D); for fixed D it is
// linear in (kd, ks): the two solves alternate inside each masking iteration.
#include <optional>
#include <vector>

#include "brdfkit/analysis/hemisphere_table.h"
#include "brdfkit/analysis/tabulated_cook_torrance.h"
#include "brdfkit/fit/metric/metric.h"

namespace brdfkit::analysis {

struct NdfEstimationOptions {
  int nodes = 90;             // table angles θ_j = (j/(n−1))² π/2: dense near θ = 0, as MERL's θh axis
  int rings = 40;             // the hemisphere table's θ nodes, counting the pole (anisotropic estimate)
  int azimuths = 64;          // the hemisphere table's φ nodes (anisotropic estimate)
  int max_iterations = 5;     // masking recomputations (seed 002 §5.1: ≤ 5)
  std::optional<double> f0;   // Schlick F0 given; nullopt: fitted (Brent on the least-squares residual)
  double smoothing = 1e-6;    // weight of the second-difference penalty on D, relative to the data term
  double tolerance = 1e-3;    // stop when D changes by less than this (max relative change at the peak scale)
};

struct NdfEstimate {
  std::vector<double> theta;            // table angles, radians
  std::vector<double> d;                // normalized D at those angles
  ParamValues values;                   // kd, ks, F0 of TabulatedCookTorrance
  int iterations = 0;                   // masking recomputations done
  double f0 = 0;
  std::vector<double> residual_history; // metric value after each masking iteration
  TabulatedCookTorrance model() const { return TabulatedCookTorrance(theta, d); }
};

// D over the hemisphere of half vectors (θ, φ) for anisotropic data: the same iteration with the
// table of hemisphere_table.h, its masking G1(ω) from the projected area σ(ω) of the current D.
struct AnisotropicNdfEstimate {
  HemisphereTable table;
  std::vector<double> d;                // normalized D at the table's nodes
  ParamValues values;                   // kd, ks, F0 per channel
  int iterations = 0;
  double f0 = 0;
  std::vector<double> residual_history; // as NdfEstimate's
  double D(const Vec3d& h) const { return table.eval(d, h); }
};

// Throws InputError when the metric has no samples or the estimate degenerates (no specular signal).
NdfEstimate estimate_tabulated_ndf(const fit::Metric& metric, const NdfEstimationOptions& opt = {});
// The same least squares on the data's own samples (MERL cells, RGL nodes: exact measured values,
// no look-up) with ngan's weighting w·cos²θi; residual_history is then √(Σ w (ρ − m)² cos²θi / Σ w).
NdfEstimate estimate_tabulated_ndf(const SampleSet& samples, const NdfEstimationOptions& opt = {});
// The hemisphere table from the data's own samples, weighted as the overload above.
AnisotropicNdfEstimate estimate_anisotropic_ndf(const SampleSet& samples, const NdfEstimationOptions& opt = {});

}  // namespace brdfkit::analysis
