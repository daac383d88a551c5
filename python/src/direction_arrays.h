#pragma once
// Arrays of directions and random numbers as the functions of the module take them: float64
// (other dtypes converted, non-contiguous arrays copied, by pybind11's array_t), either one row
// (shape (k,)) or n rows (shape (n, k)). Checked before any work: a wrong shape, a non-finite
// entry or a direction that is not a unit vector raise ValueError naming the argument and the row.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <vector>

#include "brdfkit/core/vec.h"

namespace brdfkit::python {

namespace py = pybind11;
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

struct Rows {
  const double* data = nullptr;
  std::size_t n = 0;     // rows
  std::size_t k = 0;     // columns
  bool single = false;   // given as one row of shape (k,): results drop the row axis too
  // Row i, or row 0 of a single row broadcast to every i.
  const double* row(std::size_t i) const { return data + (n == 1 ? 0 : i) * k; }
};

// Rows of `columns` entries each (columns_max > columns allows up to that many); the entries are
// checked by the functions below.
Rows rows_of(const DoubleArray& a, const char* name, std::size_t columns, std::size_t columns_max = 0);
// Unit vectors (|1 − ‖w‖²| ≤ 1e-5, so float32 input passes).
Rows directions(const DoubleArray& a, const char* name);
// Uniform numbers in [0, 1).
Rows uniforms(const DoubleArray& a, const char* name, std::size_t columns);
// Incidence angles θi in radians, each in [0, π/2): a number (ndim 0) or a 1-D array.
std::vector<double> incidence_angles(const DoubleArray& a, const char* name);
// The number of results of two row sets: equal counts, or one of them a single row (broadcast).
std::size_t paired_count(const Rows& a, const char* a_name, const Rows& b, const char* b_name);
// An array for `n` results of `k` values (shape (n, k), (k,) when single, (n,) when k is 1).
DoubleArray result_array(std::size_t n, std::size_t k, bool single);

inline Vec3d vec3(const double* p) { return Vec3d(p[0], p[1], p[2]); }

// The results of a function of two row sets: an array of k values per pair (paired_count), filled
// by fill(n, out) with the GIL released.
template <class Fill>
DoubleArray pair_results(const Rows& a, const char* a_name, const Rows& b, const char* b_name, std::size_t k,
                         Fill&& fill) {
  const std::size_t n = paired_count(a, a_name, b, b_name);
  DoubleArray out = result_array(n, k, a.single && b.single);
  double* o = out.mutable_data();
  py::gil_scoped_release release;
  fill(n, o);
  return out;
}

// Directional albedos: rgb_at(θi) (an Rgb) for each incidence angle of `theta` (incidence_angles),
// with the GIL released; shape (3,) for a number, (n, 3) for an array.
template <class RgbAt>
DoubleArray albedo_results(const DoubleArray& theta, RgbAt&& rgb_at) {
  const std::vector<double> angles = incidence_angles(theta, "theta_i");
  DoubleArray out = result_array(angles.size(), 3, theta.ndim() == 0);
  double* o = out.mutable_data();
  py::gil_scoped_release release;
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const auto a = rgb_at(angles[i]);
    for (int c = 0; c < 3; ++c) o[3 * i + std::size_t(c)] = a[c];
  }
  return out;
}

}  // namespace brdfkit::python
