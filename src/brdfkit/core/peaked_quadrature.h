#pragma once
// ∫ f over [lo, hi] for an f with one narrow peak of known position and width (a Phong lobe seen
// along a curved profile): Gauss-Legendre panels laid outwards from the point of the interval
// nearest the peak, each twice as long as the last, so a lobe of width w costs O(log(L / w))
// panels whatever its sharpness.
//
// Works for doubles and Ceres Jets: the panel edges are T, so derivatives of the integral with
// respect to the interval's ends and the peak's position are carried (the panel count, chosen
// from the scalar parts, is locally constant). Boost's adaptive rules pick their points from the
// integrand's values, which a Jet's derivative cannot follow; its Gauss-Legendre nodes serve here.
#include <algorithm>
#include <cmath>

#include <boost/math/quadrature/gauss.hpp>

#include "brdfkit/core/scalar_chain.h"

namespace brdfkit {

namespace peaked_detail {

using Rule = boost::math::quadrature::gauss<double, 10>;

// ∫ f over [a, b] (either order: the sign follows) by one 10-point Gauss-Legendre panel.
template <class T, class F> T panel(const F& f, const T& a, const T& b) {
  const T half = T(0.5) * (b - a), mid = T(0.5) * (a + b);
  T sum(0);
  for (std::size_t i = 0; i < Rule::abscissa().size(); ++i) {
    const double x = Rule::abscissa()[i], w = Rule::weights()[i];
    sum += T(w) * (x == 0.0 ? f(mid) : f(mid + T(x) * half) + f(mid - T(x) * half));
  }
  return sum * half;
}

// ∫ f from `near` to `far` (|far − near| = length), the peak at distance `gap` before `near`:
// panels of length step, 2 step, 4 step, … The first step is the width, or less when the peak
// lies outside (there the integrand falls off over width² / gap).
template <class T, class F> T outwards(const F& f, const T& near, const T& far, double gap, double width) {
  const double length = std::abs(value_of(far) - value_of(near));
  if (!(length > 0)) return T(0);
  const double step = gap > width ? width * width / gap : width;
  const T dir = (far - near) / T(length);
  T sum(0);
  double start = 0, size = step;
  while (start < length) {
    const double end = std::min(length, start + size);
    // The last edge is `far` itself, so its derivative is carried.
    const T b = end < length ? near + dir * T(end) : far;
    sum += panel<T>(f, near + dir * T(start), b);
    start = end;
    size *= 2;
  }
  return sum;
}

}  // namespace peaked_detail

// ∫_lo^hi f(x) dx, with f's peak at `peak` (inside or outside the interval) and width `width` > 0
// (the distance over which f falls by a few e-folds). Zero when hi ≤ lo.
template <class T, class F> T integrate_peaked(const F& f, const T& lo, const T& hi, const T& peak, double width) {
  namespace pd = peaked_detail;
  const double l = value_of(lo), h = value_of(hi), c = value_of(peak);
  if (!(h > l)) return T(0);
  if (c <= l) return pd::outwards<T>(f, lo, hi, l - c, width);
  if (c >= h) return -pd::outwards<T>(f, hi, lo, c - h, width);
  return pd::outwards<T>(f, peak, hi, 0.0, width) - pd::outwards<T>(f, peak, lo, 0.0, width);
}

}  // namespace brdfkit
