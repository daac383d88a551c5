#pragma once
// Smith masking for any microfacet distribution (seed 000 Eq. 6, seed 004 Eq. 4–7, DESIGN.md §4).
//
// Contract used by every distribution in ndf/ and by the models:
//   smith_lambda_numeric(ndf, tan_theta)  Λ from the distribution's P22 by numerical integration,
//                                         tabulated and interpolated so Jets carry derivatives;
//                                         distributions without a closed form return it from Lambda().
//   smith_g1(ndf, cos_theta)              1/(1 + Λ(tanθ))
//   smith_g_uncorrelated(ndf, ci, co)     G1(i) G1(o)           (the seeds' choice)
//   smith_g_correlated(ndf, ci, co)       1/(1 + Λ(i) + Λ(o))   (height-correlated option)
//
// How smith_lambda_numeric picks its method: a distribution template Ndf<T> for which
// SmithShape<Ndf> is specialized (below, in the distribution's header, or in tests) gets the
// table of shadowing/smith_table.h, shared by all scalar types (double and every Jet), its nodes
// integrated lazily and thread-safely on first use; coordinates outside the table's box, and
// distributions without a SmithShape, get the direct integral of shadowing/smith_integral.h
// (correct, and Jet-differentiable, but ~100× slower). Jets through a table get the derivative of
// its interpolant (C¹ Catmull-Rom), so a central difference of the double evaluation agrees.
//
// A SmithShape<Ndf> specialization provides
//   static constexpr int kDims;                                 1 to 3 table coordinates
//   static std::vector<SmithAxis> axes();                       box and grid of the coordinates
//   template <class T> static std::array<T, kDims> values(const Ndf<T>&);   the coordinates
// and optionally
//   static Ndf<double> make(const double* coords);              the distribution at coordinates;
//                                                               default Ndf<double>(coords), i.e.
//                                                               coordinates = params() values
//   template <class T> static T tan_edge(const T* coords);      support edge t_e (Λ = 0 for
//                                                               tanθ ≤ t_e), for compact supports
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "brdfkit/core/vec.h"
#include "brdfkit/shadowing/smith_integral.h"
#include "brdfkit/shadowing/smith_table.h"

namespace brdfkit {

// Primary template: no table (kDims = 0).
template <template <class> class Ndf> struct SmithShape {
  static constexpr int kDims = 0;
};

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

// The distributions of ndf/ without a closed-form Λ. Boxes cover each one's params() bounds;
// node counts were chosen against the direct integral (tests/shadowing/test_smith_tables.cpp and
// tests/microfacet_extra print the measured max |ΔG1| of each): scale parameters need few nodes,
// since along them the table is exact up to the t½ shift. The shapes of Blinn-Phong, Gaussian,
// GTR, Schlick rational, Sawicki rational and ABC facet sit in their own headers (their make()
// needs the complete distribution type).
template <class T> struct Sgd;
template <class T> struct ExponentialPower;
template <class T> struct Exponential;
template <> struct SmithShape<Sgd> {
  static constexpr int kDims = 2;
  // p below 0 only as an interpolation margin (the edge cells of Catmull-Rom are the weakest).
  static std::vector<SmithAxis> axes() { return {{1e-6, 2.0, 49, true}, {-0.15, 1.95, 29, false}}; }
  template <class T> static std::array<T, 2> values(const Sgd<T>& d) { return {d.alpha, d.p}; }
};
template <> struct SmithShape<ExponentialPower> {
  static constexpr int kDims = 2;
  static std::vector<SmithAxis> axes() { return {{1e-4, 2.0, 6, true}, {0.05, 10.0, 140, true}}; }
  template <class T> static std::array<T, 2> values(const ExponentialPower<T>& d) { return {d.sigma, d.p}; }
};
template <> struct SmithShape<Exponential> {
  static constexpr int kDims = 1;
  static std::vector<SmithAxis> axes() { return {{1e-3, 2.0, 8, true}}; }
  template <class T> static std::array<T, 1> values(const Exponential<T>& d) { return {d.alpha}; }
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

template <class Ndf, class T> T smith_g1(const Ndf& ndf, const T& cos_theta) {
  if (!(cos_theta > T(0))) return T(0);
  return T(1) / (T(1) + ndf.Lambda(smith_tan_theta<Ndf>(cos_theta)));
}

template <class Ndf, class T> T smith_g_uncorrelated(const Ndf& ndf, const T& cos_i, const T& cos_o) {
  return smith_g1(ndf, cos_i) * smith_g1(ndf, cos_o);
}

// Height-correlated form 1/(1 + Λ(i) + Λ(o)) (Heitz 2014 Eq. 99, cited by seed 004 §3; DESIGN.md §4).
template <class Ndf, class T> T smith_g_correlated(const Ndf& ndf, const T& cos_i, const T& cos_o) {
  if (!(cos_i > T(0) && cos_o > T(0))) return T(0);
  return T(1) / (T(1) + ndf.Lambda(smith_tan_theta<Ndf>(cos_i)) + ndf.Lambda(smith_tan_theta<Ndf>(cos_o)));
}

}  // namespace brdfkit
