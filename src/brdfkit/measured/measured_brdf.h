#pragma once
// One interface for every measured format (MERL, RGL tensor_file, Cornell, ALTA slices).
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "brdfkit/core/vec.h"
#include "brdfkit/measured/sample_set.h"

namespace brdfkit {

class MeasuredBrdf {
 public:
  virtual ~MeasuredBrdf() = default;
  virtual std::string format() const = 0;      // "merl", "rgl", "cornell", "alta"
  virtual std::string path() const = 0;        // the file it was read from (or a synthetic name)
  virtual std::string dimensions() const = 0;  // human-readable shape of the data
  // ρ(wi, wo) per channel where the data answer it (tabulated formats: anywhere above the
  // horizon; scattered formats: nullopt). nullopt also where the cell was not measured.
  virtual std::optional<Rgb> eval(const Vec3d& wi, const Vec3d& wo) const = 0;
  // The measurement as samples (a MERL cell, an RGL node, a Cornell line, an ALTA row).
  virtual SampleSet samples() const = 0;
  // Directional albedo (per channel) at each incidence angle θi (radians) the data hold, computed
  // from the samples themselves: for scattered formats whose eval() cannot be integrated (Cornell).
  // Empty (the default) where eval() answers and albedo is integrated from it.
  virtual std::vector<std::pair<double, Rgb>> albedos_from_samples() const { return {}; }
};

}  // namespace brdfkit
