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
// PLACEHOLDER: the numeric Λ below is a stub until shadowing/ is implemented.
#include <cmath>

#include "brdfkit/core/vec.h"

namespace brdfkit {

template <class Ndf, class T> T smith_lambda_numeric(const Ndf&, const T&) { return T(0); }

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

template <class Ndf, class T> T smith_g_correlated(const Ndf& ndf, const T& cos_i, const T& cos_o) {
  if (!(cos_i > T(0) && cos_o > T(0))) return T(0);
  return T(1) / (T(1) + ndf.Lambda(smith_tan_theta<Ndf>(cos_i)) + ndf.Lambda(smith_tan_theta<Ndf>(cos_o)));
}

}  // namespace brdfkit
