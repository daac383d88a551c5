#include "direction_arrays.h"

#include <fmt/format.h>

#include <cmath>

#include "brdfkit/core/error.h"

namespace brdfkit::python {

Rows rows_of(const DoubleArray& a, const char* name, std::size_t columns, std::size_t columns_max) {
  if (columns_max < columns) columns_max = columns;
  const auto width = [&] {
    return columns == columns_max ? std::to_string(columns) : fmt::format("{} or {}", columns, columns_max);
  };
  Rows r;
  r.data = a.data();
  if (a.ndim() == 1) {
    r.single = true;
    r.n = 1;
    r.k = std::size_t(a.shape(0));
  } else if (a.ndim() == 2) {
    r.n = std::size_t(a.shape(0));
    r.k = std::size_t(a.shape(1));
  } else {
    throw InputError(name, fmt::format("expected an array of shape (n, {}) or ({},), got {} dimensions", width(),
                                       width(), a.ndim()));
  }
  if (r.k < columns || r.k > columns_max)
    throw InputError(name, fmt::format("expected {} columns, got {}", width(), r.k));
  return r;
}

namespace {

[[noreturn]] void not_finite(const char* name, std::size_t row) {
  throw InputError(fmt::format("{}[{}]", name, row), "is not finite (NaN or infinite)");
}

}  // namespace

// One pass over the rows: a NaN or infinite entry also fails the norm test, and is named as such.
Rows directions(const DoubleArray& a, const char* name) {
  Rows r = rows_of(a, name, 3);
  for (std::size_t i = 0; i < r.n; ++i) {
    const double* w = r.row(i);
    const double n2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    if (std::abs(n2 - 1) <= 1e-5) continue;
    if (!std::isfinite(n2)) not_finite(name, i);
    throw InputError(fmt::format("{}[{}]", name, i), fmt::format("is not a unit vector (norm {:.6g})", std::sqrt(n2)));
  }
  return r;
}

Rows uniforms(const DoubleArray& a, const char* name, std::size_t columns) {
  Rows r = rows_of(a, name, columns);
  for (std::size_t i = 0; i < r.n * r.k; ++i)
    if (!std::isfinite(r.data[i])) not_finite(name, i / r.k);
    else if (!(r.data[i] >= 0 && r.data[i] < 1))
      throw InputError(fmt::format("{}[{}]", name, i / r.k), fmt::format("{:.17g} is not in [0, 1)", r.data[i]));
  return r;
}

std::vector<double> incidence_angles(const DoubleArray& a, const char* name) {
  if (a.ndim() > 1) throw InputError(name, fmt::format("expected a number or a 1-D array, got {} dimensions", a.ndim()));
  std::vector<double> out(a.data(), a.data() + a.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    if (!(out[i] >= 0 && out[i] < kPi / 2))
      throw InputError(fmt::format("{}[{}]", name, i), fmt::format("{:.17g} rad is not in [0, pi/2)", out[i]));
  return out;
}

std::size_t paired_count(const Rows& a, const char* a_name, const Rows& b, const char* b_name) {
  if (a.n == b.n || b.n == 1) return a.n;
  if (a.n == 1) return b.n;
  throw InputError(fmt::format("{}, {}", a_name, b_name),
                   fmt::format("{} rows and {} rows: expected as many, or one of them a single row", a.n, b.n));
}

DoubleArray result_array(std::size_t n, std::size_t k, bool single) {
  if (single) return k == 1 ? DoubleArray(std::vector<py::ssize_t>{}) : DoubleArray(py::ssize_t(k));
  if (k == 1) return DoubleArray(py::ssize_t(n));
  return DoubleArray({py::ssize_t(n), py::ssize_t(k)});
}

}  // namespace brdfkit::python
