#pragma once
// One interface for every measured format (MERL, RGL tensor_file, Cornell, ALTA slices).
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "brdfkit/core/vec.h"
#include "brdfkit/measured/sample_set.h"

namespace brdfkit {

namespace merl {
class Table;
}

class MeasuredBrdf {
 public:
  virtual ~MeasuredBrdf() = default;
  virtual std::string format() const = 0;      // "merl", "rgl", "cornell", "alta"
  virtual std::string path() const = 0;        // the file it was read from (or a synthetic name)
  virtual std::string dimensions() const = 0;  // human-readable shape of the data
  // ρ(wi, wo) per channel where the data answer it (tabulated formats: anywhere above the
  // horizon; scattered formats: nullopt). nullopt also where the cell was not measured.
  virtual std::optional<Rgb> eval(const Vec3d& wi, const Vec3d& wo) const = 0;
  // out[k] = eval(wi, wo[k]) for every k, the same values: formats whose look-up has a part that
  // depends on wi alone (RGL's row of the warp) do it once per row.
  virtual void eval_row(const Vec3d& wi, std::span<const Vec3d> wo, std::vector<std::optional<Rgb>>& out) const {
    out.resize(wo.size());
    for (size_t k = 0; k < wo.size(); ++k) out[k] = eval(wi, wo[k]);
  }
  // Whether ρ is unchanged by a rotation of both directions about the normal. Metrics integrate
  // anisotropic data over their own samples (all incidence azimuths), not over a grid with wi at
  // φ = 0 (fit/metric/metric.cpp).
  virtual bool isotropic() const { return true; }
  // The data's own MERL cells when it is a MERL table (metrics then integrate over the cells,
  // fit/metric/metric_cells.h); nullptr otherwise.
  virtual const merl::Table* merl_cells() const { return nullptr; }
  // The measurement as samples (a MERL cell, an RGL node, a Cornell line, an ALTA row).
  virtual SampleSet samples() const = 0;
  // Directional albedo (per channel) at each incidence angle θi (radians) the data hold, computed
  // from the samples themselves: for scattered formats whose eval() cannot be integrated (Cornell).
  // Empty (the default) where eval() answers and albedo is integrated from it.
  virtual std::vector<std::pair<double, Rgb>> albedos_from_samples() const { return {}; }
};

}  // namespace brdfkit
