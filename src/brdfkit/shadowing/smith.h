#pragma once
// Smith masking for any microfacet distribution (seed 000 Eq. 6, seed 004 Eq. 4–7, DESIGN.md §4).
//
// What the models use:
//   smith_lambda(ndf, tan_theta)          Λ: the closed form, or the numeric one
//   smith_lambda_numeric(ndf, tan_theta)  Λ from the distribution's P22 by numerical integration,
//                                         tabulated and interpolated so Jets carry derivatives
//   smith_g1(ndf, cos_theta)              1/(1 + Λ(tanθ))
//   smith_g_uncorrelated(ndf, ci, co)     G1(i) G1(o)           (the seeds' choice)
//   smith_g_correlated(ndf, ci, co)       1/(1 + Λ(i) + Λ(o))   (height-correlated option)
//
// How smith_lambda_numeric picks its method: a distribution template Ndf<T> for which
// SmithShape<Ndf> is specialized (ndf/distribution.h: in the distribution's header, or in tests)
// gets the table of shadowing/smith_table.h, shared by all scalar types (double and every Jet), its
// nodes integrated lazily and thread-safely on first use; coordinates outside the table's box, and
// distributions without a SmithShape, get the direct integral of shadowing/smith_integral.h
// (correct, and Jet-differentiable, but ~100× slower). Jets through a table get the derivative of
// its interpolant (C¹ Catmull-Rom), so a central difference of the double evaluation agrees.
// smith_lambda(ndf, t) takes the distribution's closed form where it has one (Lambda()), the
// numeric Λ otherwise; a distribution that is not normalized names the one whose Λ it has
// (smith_form()).
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "brdfkit/core/vec.h"
#include "brdfkit/shadowing/smith_integral.h"
#include "brdfkit/ndf/distribution.h"
#include "brdfkit/shadowing/smith_table.h"

namespace brdfkit {

// The table of a distribution family (one per template, whatever the scalar type), its nodes
// built lazily. C++ function-local statics initialise exactly once, and other threads wait for it.
template <template <class> class Ndf> Ndf<double> smith_shape_make(const double* coords) {
  if constexpr (requires { SmithShape<Ndf>::make(coords); })
    return SmithShape<Ndf>::make(coords);
  else
    return Ndf<double>(coords);
}
template <template <class> class Ndf> const SmithLambdaTable& smith_lambda_table() {
  using Shape = SmithShape<Ndf>;
  SmithLambdaTable::EdgeFn edge;
  if constexpr (requires(const double* c) { Shape::tan_edge(c); })
    edge = [](const double* c) { return Shape::tan_edge(c); };
  static const SmithLambdaTable table(
      Shape::axes(),
      [](const double* c, double t) {
        const Ndf<double> ndf = smith_shape_make<Ndf>(c);
        return smith_lambda_integral(ndf, t);
      },
      edge);
  return table;
}

// Tables for the scale families with closed forms exist too: the tests check the table against
// those closed forms (the distributions themselves use their closed-form Λ).
template <class T> struct Beckmann;
template <class T> struct Ggx;
template <> struct SmithShape<Beckmann> {
  static constexpr int kDims = 1;
  static std::vector<SmithAxis> axes() { return {{1e-3, 2.0, 12, true}}; }
  template <class T> static std::array<T, 1> values(const Beckmann<T>& d) { return {d.alpha}; }
};
template <> struct SmithShape<Ggx> {
  static constexpr int kDims = 1;
  static std::vector<SmithAxis> axes() { return {{1e-3, 2.0, 12, true}}; }
  template <class T> static std::array<T, 1> values(const Ggx<T>& d) { return {d.alpha}; }
};

// Λ of a distribution that has no SmithShape (or is not a one-parameter template): direct integral.
template <class Ndf, class T> T smith_lambda_numeric(const Ndf& ndf, const T& tan_theta) {
  return smith_lambda_integral(ndf, tan_theta);
}

template <template <class> class Ndf, class T, class U>
  requires(SmithShape<Ndf>::kDims > 0)
U smith_lambda_numeric(const Ndf<T>& ndf, const U& tan_theta) {
  using Shape = SmithShape<Ndf>;
  const std::array<T, Shape::kDims> p = Shape::values(ndf);
  double ps[Shape::kDims];
  for (int k = 0; k < Shape::kDims; ++k) ps[k] = smith_detail::scalar(p[k]);
  const SmithLambdaTable& table = smith_lambda_table<Ndf>();
  if (!table.covers(ps)) return smith_lambda_integral(ndf, tan_theta);
  // Jet tanθ with double parameters (or the reverse) interpolates in the Jet type.
  std::array<U, Shape::kDims> pu;
  for (int k = 0; k < Shape::kDims; ++k) pu[k] = U(p[k]);
  U edge(0);
  if constexpr (requires { Shape::tan_edge(pu.data()); }) edge = Shape::tan_edge(pu.data());
  return table.lambda(pu.data(), tan_theta, edge);
}

template <class Ndf, class T> T smith_tan_theta(const T& cos_theta) {
  using std::sqrt;
  return sqrt(std::max(T(0), T(1) - cos_theta * cos_theta)) / cos_theta;
}

// Λ(tanθ): the closed form, the form of smith_form(), or the numeric Λ.
template <class Ndf, class T> T smith_lambda(const Ndf& ndf, const T& tan_theta) {
  if constexpr (requires { ndf.Lambda(tan_theta); })
    return ndf.Lambda(tan_theta);
  else if constexpr (requires { ndf.smith_form(); })
    return smith_lambda_numeric(ndf.smith_form(), tan_theta);
  else
    return smith_lambda_numeric(ndf, tan_theta);
}

template <class Ndf, class T> T smith_g1(const Ndf& ndf, const T& cos_theta) {
  if (!(cos_theta > T(0))) return T(0);
  return T(1) / (T(1) + smith_lambda(ndf, smith_tan_theta<Ndf>(cos_theta)));
}

template <class Ndf, class T> T smith_g_uncorrelated(const Ndf& ndf, const T& cos_i, const T& cos_o) {
  return smith_g1(ndf, cos_i) * smith_g1(ndf, cos_o);
}

// Height-correlated form 1/(1 + Λ(i) + Λ(o)) (Heitz 2014 Eq. 99, cited by seed 004 §3; DESIGN.md §4).
template <class Ndf, class T> T smith_g_correlated(const Ndf& ndf, const T& cos_i, const T& cos_o) {
  if (!(cos_i > T(0) && cos_o > T(0))) return T(0);
  return T(1) / (T(1) + smith_lambda(ndf, smith_tan_theta<Ndf>(cos_i)) + smith_lambda(ndf, smith_tan_theta<Ndf>(cos_o)));
}

}  // namespace brdfkit
