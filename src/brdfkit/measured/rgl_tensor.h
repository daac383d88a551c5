#pragma once
// RGL `tensor_file` BRDFs (EPFL material database, Dupuy & Jakob 2018): reader and evaluation.
// Byte layout: data/README.md; evaluation: DESIGN.md §2 and Dupuy & Jakob 2018 §5–6, the scheme of
// Mitsuba 3's `measured` plugin and pbrt-v4's MeasuredBxDF (with pbrt-v4 PR #215's cosine fix).
//
// Roles of the two directions: the tables are conditioned on one direction ωc (their theta_i/phi_i
// axes). brdfkit's eval(wi, wo) takes ωc = wi, the illumination direction (DESIGN.md §7), and
// ωx = wo. The data are not exactly reciprocal, so eval(wi, wo) ≠ eval(wo, wi) in general.
//
// Incidence azimuths (Mitsuba 3 `measured`): a file with one or two phi_i entries is isotropic;
// with more, every table is conditioned on (φi, θi), half vectors keep their absolute azimuth, and
// a file may hold 1/2 of the incidence azimuths (ρ unchanged by a half turn of both directions) or
// 1/4 (also by mirrors about the x and y axes); a look-up folds the pair into the stored range.
// Tables are indexed by slice = p · theta_i().size() + t for phi_i node p and theta_i node t.
#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "brdfkit/measured/marginal_warp_2d.h"
#include "brdfkit/measured/measured_brdf.h"
#include "brdfkit/measured/sample_set.h"

namespace brdfkit {

class RglBrdf final : public MeasuredBrdf {
 public:
  // Reads and validates the file; throws InputError naming the file and the field at fault.
  explicit RglBrdf(const std::filesystem::path& file);

  std::string format() const override { return "rgl"; }
  std::string path() const override { return path_; }
  std::string dimensions() const override;
  // ρ(wi, wo) in sr⁻¹ with ωc = wi; raw table values (may be < 0 where the file holds noise).
  std::optional<Rgb> eval(const Vec3d& wi, const Vec3d& wo) const override;
  // The table nodes: for each slice and each node of the rgb grid, the direction pair the VNDF warp
  // maps it to (nodes whose wo falls below the horizon are skipped; the θi node on the horizon
  // too), its raw value, and weight = solid angle of wo the node stands for within its slice
  // (∫ |dωo/du| over the node's cell, node ± ½ spacing, of the warp's unit square) times the
  // slice's share of the incidence azimuths, so that the weights of one θi sum to 2π and
  // Σ weight·ρ·cosθo ≈ the azimuthal mean of the albedo. A file holding 1/2 or 1/4 of the azimuths
  // gives every node once per image under its symmetry.
  SampleSet samples() const override;
  bool isotropic() const override { return isotropic_; }

  // out[k] = eval(wi, wo[k]) for every k, the same values by the same operations, with what
  // depends on wi alone (its angles, its θi interpolation weights, σ(wi)) computed once: the
  // look-ups of a metric's chunk share wi.
  void eval_row(const Vec3d& wi, std::span<const Vec3d> wo, std::vector<std::optional<Rgb>>& out) const override;
  // ρ with the table conditioned on `wc` and the other direction `wx`. With `cosine_of_other`
  // false the cosine is taken on ωc (pbrt-v4 before PR #215): only for tests that show it wrong.
  std::optional<Rgb> eval_conditioned(const Vec3d& wc, const Vec3d& wx, bool cosine_of_other = true) const;
  // ρ's luminance from the file's own `luminance` table through the same warp and factors as
  // eval(): a second table, so it cross-checks eval() (linear-sRGB Y of `rgb`).
  std::optional<double> eval_luminance(const Vec3d& wi, const Vec3d& wo) const;
  // The point of the table's unit square (x: columns, y: rows) that eval(wc, wx) interpolates.
  std::optional<Vec2d> table_coordinates(const Vec3d& wc, const Vec3d& wx) const;
  // Directional albedo a(wi) = ∫ ρ(wi, wo) cosθo dωo by an n×n midpoint rule in the unit square of
  // the VNDF warp (so the points follow the lobe), per channel.
  Rgb albedo(const Vec3d& wi, int n = 64) const;

  std::string description() const { return description_; }
  size_t negative_values() const { return negative_values_; }  // rgb/spectra entries < 0 (noise)
  bool spectral() const { return spectral_; }                  // converted from `spectra`
  bool jacobian() const { return jacobian_; }
  const std::vector<float>& theta_i() const { return theta_i_; }
  const std::vector<float>& phi_i() const { return phi_i_; }
  int reduction() const { return reduction_; }  // copies of the stored azimuth range in the circle
  size_t slices() const { return phi_i_.size() * theta_i_.size(); }
  Vec3d incidence(size_t slice) const;      // ωc of a slice's nodes
  int grid_size() const { return grid_; }  // rgb grid is grid × grid per slice
  // Raw table node values at a slice, grid row y, column x (rgb after spectral conversion; the
  // file's `luminance` table).
  Rgb rgb_node(size_t slice, int y, int x) const;
  double luminance_node(size_t slice, int y, int x) const;
  // The file's microfacet tables through the reader's interpolants: D(m) and the projected area
  // σ(ω) = ∫ D(m) max(0, ω·m) dωm that divides every value.
  double ndf(const Vec3d& m) const;
  double sigma(const Vec3d& w) const;
  // The direction pair of a node (nullopt where wo is below the horizon), as samples() uses.
  std::optional<std::pair<Vec3d, Vec3d>> node_directions(size_t slice, int y, int x) const;

 private:
  // Sign flips of x and y that take a pair into the stored azimuths (identity for a full circle).
  struct Fold {
    double sx = 1, sy = 1;
    Vec3d operator()(const Vec3d& v) const { return Vec3d(sx * v.x(), sy * v.y(), v.z()); }
  };
  Fold fold(const Vec3d& wc) const;
  std::vector<Fold> images() const;
  std::vector<double> azimuth_shares() const;  // per phi_i node, summing to 1/reduction
  // Where the VNDF warp of a slice sends a point u of the unit square: the half vector's
  // coordinates, the pair, and |dωx/du| (0 below the horizon).
  struct NodeWarp {
    Vec2d u_m;
    Vec3d wc, wx;
    double weight;
  };
  NodeWarp node_warp(size_t slice, const Vec2d& u) const;
  double node_weight(size_t slice, int y, int x) const;

  std::string path_, description_;
  bool spectral_ = false, jacobian_ = true, isotropic_ = true;
  int reduction_ = 1;
  size_t negative_values_ = 0;
  int grid_ = 0;
  std::vector<float> theta_i_, phi_i_;
  MarginalWarp2D ndf_, sigma_, vndf_, luminance_;
  std::array<MarginalWarp2D, 3> rgb_;           // one interpolant per channel (bilinear, no CDF)
  std::array<std::vector<float>, 3> rgb_raw_;   // [slice][y][x] per channel
  std::vector<float> luminance_raw_;            // [slice][y][x]
};

// Reads an RGL tensor_file BRDF (see RglBrdf); for measured/load.cpp.
std::unique_ptr<MeasuredBrdf> read_rgl(const std::filesystem::path& file);

}  // namespace brdfkit
