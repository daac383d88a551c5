#pragma once
// How a model's value depends on its colours, found by probing the model at fixed direction pairs
// (so any model of the catalogue, sums and wrappers included, is handled without declaring it).
//
// Colours are the per-channel parameters flagged `linear` (kd, ks …): with the shape fixed,
// ρ_c = Σ_j β_cj b_j, b_j the model with colour j = 1 and the others 0. Variable projection (seed
// 002 §3) solves β by linear least squares inside every evaluation. A per-channel parameter P on
// which ρ depends affinely and only through one colour L (Schlick's F0 under ks: ks F = ks F0 +
// ks (1 − F0)(1 − cosθd)⁵) joins the linear sub-problem too (DESIGN.md §12: kd, ks·F0, ks·(1 − F0)
// are the linear colours): L b(P) = u b(P_hi) + v b(P_lo), u = L t, v = L (1 − t),
// t = (P − P_lo)/(P_hi − P_lo), u, v ≥ 0; so L = u + v, P = P_lo + (P_hi − P_lo) u/(u + v).
#include <cstddef>
#include <utility>
#include <vector>

#include "brdfkit/core/param.h"
#include "brdfkit/core/vec.h"
#include "brdfkit/fit/engine/solver_variables.h"
#include "brdfkit/models/model.h"

namespace brdfkit::fit {

// Probe direction pairs per property check, away from the mirror direction and the horizon.
inline constexpr int kProbePairs = 12;
// More pairs for "the channel changes nothing": wavelength effects can be small at some pairs.
inline constexpr int kChannelProbePairs = 16;
// Relative distance from the mid-point line within which ρ(P) counts as affine in P.
inline constexpr double kAffineTolerance = 1e-9;
// Where a shape probe moves each variable: this fraction of its box from the lower bound (an
// arbitrary interior point, unlikely to coincide with a default).
inline constexpr double kShapeProbeFraction = 0.371;
// Linear bases the colour sub-problem solves exactly (box_least_squares enumerates 3^K cases).
inline constexpr std::size_t kMaxBases = 6;

// Probe pair k < kChannelProbePairs.
std::pair<Vec3d, Vec3d> probe_pair(int k);

// One linear basis: ρ with colour `lin` = 1, the other colours 0, and (for a Fresnel-like
// parameter paired with it) parameter `affine` set to `affine_value`.
struct LinearBasis {
  int lin;
  int affine = -1;
  double affine_value = 0;
};

struct LinearStructure {
  std::vector<int> colours;        // per-channel parameters ρ is linear in; empty: none usable
  std::vector<int> paired;         // per parameter: the colour it rides on affinely, or −1
  std::vector<LinearBasis> bases;  // ρ_c = Σ_j β_cj b_j
};

// The model's colours; with `pair_affine`, Fresnel-like parameters paired to them and the bases
// expanded (two per pair). Colours are dropped when ρ does not vanish with all of them at 0 (a
// term free of them breaks ρ = Σ β b: Ashikhmin-Shirley's lobe, whose colour is a Schlick F0).
// InputError for more than kMaxBases bases when pairing (the projected sub-problem's limit).
LinearStructure probe_linear_structure(const Model& model, bool pair_affine);

// Parameters the projected objective solves itself (`project`): the colours and those paired with
// them; none otherwise. SolverVariables' `solved_inside`.
std::vector<bool> solved_inside(const LinearStructure& s, bool project);

// Channel c's parameter vector of basis j at the shape of pv: colours 0 except the basis's own
// (1), its paired parameter at the basis's bound.
std::vector<double> basis_params(const ParamValues& pv, int c, const std::vector<LinearBasis>& bases, std::size_t j);

// Whether basis j is the same for every shape (probed at the table's defaults and with every
// variable that is not a colour moved into its box), for basis classes q < classes: then it is
// evaluated once per sample stride.
bool basis_independent_of_shape(const Model& model, const SolverVariables& vars, const std::vector<LinearBasis>& bases,
                                std::size_t j, int classes);

// Whether the model gives channels 1 and 2 the value of channel 0 at parameters p (probed).
bool same_in_every_channel(const Model& model, const std::vector<double>& p);

}  // namespace brdfkit::fit
