#pragma once
// The back-scattering slice wi = wo (θd = 0) of a measured BRDF and the distributions it implies
// (seed 000 §4.1, Eq. 7, Fig. 3): on that slice h = wi and
//   ρ(θh) = ρd/π + Fr/π · D(θh) G1(θh)² / cos²θh,                         (seed 000 Eq. 7, 12)
// so each distribution family is fitted to the slice per channel (ρd, Fr and its shape
// parameters; Ceres, bounded Levenberg-Marquardt, seeded starts) and the data's own D follows
// from inverting Eq. 7 with the fitted ρd, Fr and G1.
//
// Which data answer: an ALTA θd = 0 slice (its rows), and every format whose eval() answers at
// wi = wo (MERL tables; RGL files, which have no exact θd = 0 slice: the tables are evaluated
// at wi = wo). Scattered data (Cornell) miss the retro-reflection neighbourhood: InputError.
#include <array>
#include <string>
#include <vector>

#include "brdfkit/core/vec.h"
#include "brdfkit/measured/measured_brdf.h"

namespace brdfkit::analysis {

struct BackscatterSlice {
  std::vector<double> theta_h;  // radians, increasing
  std::vector<Rgb> value;       // m(h, h), sr⁻¹
  std::vector<double> weight;   // solid angle of the band of half vectors the sample stands for
};

enum class SliceFitSpace {
  Linear,  // seed 000 Eq. 12: Σ w (m − ρ)², w = solid angle: the peak dominates
  Log,     // Σ w (ln m − ln ρ)²: peak and tail alike, the log scale Fig. 3 is read on
};

struct BackscatterOptions {
  double max_theta_h_deg = 80;  // grazing measurements are unreliable (DESIGN.md §2)
  int nodes = 90;               // for tables: θh = ((k+½)/n)² π/2, MERL's θh cell centres
  SliceFitSpace space = SliceFitSpace::Linear;
  std::vector<std::string> families = {"beckmann", "ggx", "exponential", "sgd", "exponential-power"};
};

struct BackscatterFit {
  std::string family;
  std::vector<std::string> shape_names;
  std::array<std::vector<double>, 3> shape;  // per channel (seed 000 §5.1 fits channels separately)
  std::array<double, 3> rho_d{}, fr{};
  // Per channel: √(Σ w (m − ρ)² / Σ w) / max m  and  √(Σ w (ln m − ln ρ)² / Σ w) over m > 0.
  std::array<double, 3> error_linear{}, error_log{};
  double mean_error_linear = 0, mean_error_log = 0;  // over the channels
  std::array<std::vector<double>, 3> model;           // fitted ρ(θh) at the slice's angles
  std::array<std::vector<double>, 3> fitted_d;        // the family's D(θh)
  std::array<std::vector<double>, 3> implied_d;       // (m − ρd/π) π cos²θh / (Fr G1²): the data's D
};

struct BackscatterAnalysis {
  BackscatterSlice slice;
  SliceFitSpace space = SliceFitSpace::Linear;
  std::vector<BackscatterFit> fits;  // in options.families order
};

// The distribution families the slice fit knows: every distribution of ndf/distributions.h, in
// that order (BackscatterOptions::families defaults to five of them).
const std::vector<std::string>& backscatter_families();

// The slice (InputError naming the file when the data have no value on it).
BackscatterSlice backscatter_slice(const MeasuredBrdf& data, const BackscatterOptions& opt = {});
BackscatterAnalysis analyze_backscatter(const MeasuredBrdf& data, const BackscatterOptions& opt = {});
BackscatterAnalysis analyze_backscatter(const BackscatterSlice& slice, const BackscatterOptions& opt = {});

}  // namespace brdfkit::analysis
