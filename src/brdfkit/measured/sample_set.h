#pragma once
// Scattered samples: the form every measured format takes for fitting and metrics (DESIGN.md §2).
// Structure of arrays, so evaluation loops over samples vectorize.
#include <array>
#include <cstdint>
#include <vector>

#include "brdfkit/core/pair_arrays.h"
#include "brdfkit/core/vec.h"

namespace brdfkit {

// Direction pairs (PairArrays): wi towards the light, wo towards the viewer (unit vectors, z > 0).
struct SampleSet : PairArrays {
  std::array<std::vector<double>, 3> rgb;  // measured ρ per channel, sr⁻¹, raw (may be < 0: noise)
  std::vector<double> weight;              // quadrature weight of the sample (solid-angle measure)
  std::vector<std::uint8_t> valid;         // 0 = not measured: excluded from fits and metrics
  size_t size() const { return weight.size(); }
  void reserve(size_t n);
  void push_back(const Vec3d& wi, const Vec3d& wo, const Rgb& value, double w, bool is_valid);
  Rgb value(size_t k) const { return {rgb[0][k], rgb[1][k], rgb[2][k]}; }
};

}  // namespace brdfkit
