#pragma once
// Scattered samples: the form every measured format takes for fitting and metrics (DESIGN.md §2).
// Structure of arrays, so evaluation loops over samples vectorize.
#include <array>
#include <cstdint>
#include <vector>

#include "brdfkit/core/vec.h"

namespace brdfkit {

struct SampleSet {
  // Direction pairs: wi towards the light, wo towards the viewer (unit vectors, z > 0).
  std::vector<double> wi_x, wi_y, wi_z, wo_x, wo_y, wo_z;
  std::array<std::vector<double>, 3> rgb;  // measured ρ per channel, sr⁻¹, raw (may be < 0: noise)
  std::vector<double> weight;              // quadrature weight of the sample (solid-angle measure)
  std::vector<std::uint8_t> valid;         // 0 = not measured: excluded from fits and metrics

  size_t size() const { return weight.size(); }
  void reserve(size_t n);
  void push_back(const Vec3d& wi, const Vec3d& wo, const Rgb& value, double w, bool is_valid);
  Vec3d wi(size_t k) const { return {wi_x[k], wi_y[k], wi_z[k]}; }
  Vec3d wo(size_t k) const { return {wo_x[k], wo_y[k], wo_z[k]}; }
  Rgb value(size_t k) const { return {rgb[0][k], rgb[1][k], rgb[2][k]}; }
};

}  // namespace brdfkit
