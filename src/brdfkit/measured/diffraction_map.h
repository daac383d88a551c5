#pragma once
// Where diffraction dominates a measured BRDF (seed 004 §4.2, DESIGN.md §8 `hp-2step`): with the
// Fresnel term locally constant, a diffraction lobe is a function of f = (2/λ) sinθh cosθd only
// (seed 004 Eq. 11, 13), so ∇ρ and ∇f are colinear there: det(∇ρ, ∇f) ≈ 0 (Eq. 14–15).
// As the paper does: ρ is averaged over φd into a (θh, θd) table, with its variance and sample
// count; derivatives are finite differences of log ρ (seed 004 Fig. 5 plots log ρ) in radians;
// ∇f is analytic per channel wavelength (DESIGN.md §2); a cell is diffraction-dominated where
// |det| < threshold (the paper's 10⁻²; not scale-free, hence an option).
#include <array>
#include <vector>

#include "brdfkit/core/vec.h"
#include "brdfkit/measured/measured_brdf.h"

namespace brdfkit {

struct DiffractionOptions {
  int theta_h_cells = 90;     // θh = ((i+½)/n)² π/2 (MERL's θh axis)
  int theta_d_cells = 90;     // θd = (j+½)/n · π/2
  int phi_d_samples = 90;     // φd = (k+½)/n · π (isotropy and reciprocity fold φd into [0, π))
  double max_theta = 1.4;     // radians: seed 004 §5.8 drops θi or θo ≥ 1.4
  double threshold = 1e-2;    // seed 004 §4.2
};

struct DiffractionCell {
  double theta_h = 0, theta_d = 0;
  Rgb mean = Rgb::Zero(), variance = Rgb::Zero();  // of ρ over φd
  int count = 0;                                   // φd samples with a value
  std::array<double, 3> det{};                     // det(∇ log ρ, ∇f) per channel
  std::array<bool, 3> has_det{};                   // false where log ρ or a neighbour is missing
  std::array<bool, 3> diffraction{};               // |det| < threshold
};

struct DiffractionMap {
  int theta_h_cells = 0, theta_d_cells = 0;
  double threshold = 0;
  std::vector<DiffractionCell> cells;  // row-major: index = i_θh · theta_d_cells + j_θd
  std::array<int, 3> classified{}, diffraction_cells{};
  std::array<double, 3> diffraction_fraction{};  // diffraction_cells / classified
};

// Throws InputError (naming the file) when the data answer eval() nowhere on the grid.
DiffractionMap diffraction_map(const MeasuredBrdf& data, const DiffractionOptions& opt = {});

}  // namespace brdfkit
