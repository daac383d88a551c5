#pragma once
// A MERL table as a MeasuredBrdf (DESIGN.md §2): eval = the reference reader's nearest-cell
// look-up (nullopt for cells not measured and below the horizon); samples = one per valid cell.
#include <filesystem>
#include <memory>
#include <string>

#include "brdfkit/measured/measured_brdf.h"
#include "brdfkit/measured/merl.h"

namespace brdfkit {

class MerlBrdf final : public MeasuredBrdf {
 public:
  MerlBrdf(merl::Table table, std::string path) : table_(std::move(table)), path_(std::move(path)) {}

  std::string format() const override { return "merl"; }
  std::string path() const override { return path_; }
  std::string dimensions() const override { return "90 x 90 x 180 (theta_h x theta_d x phi_d)"; }
  std::optional<Rgb> eval(const Vec3d& wi, const Vec3d& wo) const override { return table_.lookup(wi, wo); }
  // eval's cells, found a block at a time (merl_row_cells.h).
  void eval_row(const Vec3d& wi, std::span<const Vec3d> wo, std::vector<std::optional<Rgb>>& out) const override;
  // Interpolating alternative to eval (merl::Table::lookup_trilinear).
  std::optional<Rgb> eval_trilinear(const Vec3d& wi, const Vec3d& wo) const { return table_.lookup_trilinear(wi, wo); }

  // One sample per valid cell whose centre directions are above the horizon (a valid cell below
  // it can only come from a hand-made file), in file order, at the cell centre with φh = 0,
  // value = raw × scale. weight = cell_weight(): the measure of the cell in the space of direction
  // pairs, so Σ weight·f ≈ ∫_{H²}∫_{H²} f(wi, wo) dωi dωo for an isotropic, reciprocal f; summed
  // over every cell above the horizon it approaches (2π)².
  SampleSet samples() const override;

  const merl::Table& table() const { return table_; }
  const merl::Table* merl_cells() const override { return &table_; }

 private:
  merl::Table table_;
  std::string path_;
};

// The measure ∫ dωi dωo of the pairs that map to cell c: with dωi dωo = 4 cos θd dωh dωd
// (dωo = 4 (wi·h) dωh at fixed wi, and wi = R(h)·d is a rotation of d at fixed h), integrated
// exactly over the cell: 2π (cos θh₀ − cos θh₁) [φh] · 4 · ½ (sin²θd₁ − sin²θd₀) · 2·(π/180) [φd
// and φd + π, which share the cell by reciprocity]. Cells crossing the horizon count whole.
double merl_cell_weight(const merl::Cell& c);

// Reads a MERL .binary file (merl::read, InputError on bad input); for measured/load.cpp.
std::unique_ptr<MerlBrdf> read_merl(const std::filesystem::path& file);

}  // namespace brdfkit
