#pragma once
// The surface of Poulin & Fournier 1990: parallel cylinders of radius 1 whose axes lie along
// the lobe's tangent, raised h above the base plane (0 < h ≤ 1, so the profile is a heightfield)
// and d apart (the flat gap between the footprints of neighbours). In the cross-section (y across
// the cylinders, z up) one period P = 2 s + d is
//   the arc  (sin θ, h − 1 + cos θ), θ ∈ [−θm, θm], normal (sin θ, cos θ), cos θm = 1 − h, s = sin θm,
//   the gap  (y, 0), y ∈ [s, s + d], normal (0, 1).
// A direction enters only through its angle `a` in the cross-section (from z, towards +y); since
// the cylinders are infinitely long, a point is lit (or seen) exactly when the 2-D ray from it
// at angle a misses the neighbour cylinder on that side (a ray rising past the nearest neighbour
// clears all others), and, on the arc, faces it.
//
// The lit part of each piece is one interval (derived here; PF 1990 works from the same silhouette,
// and tests/models/reference/test_poulin_fournier_reference.cpp checks it by ray casting). For a ≥ 0, with offsets o(q) = q · (cos a, −sin a) across the rays, a
// point is shadowed exactly when its offset exceeds the smallest offset o* of the neighbour's
// visible cap: the tangent point c' − (cos a, −sin a) when it lies above the base (a ≥ π/2 − θm),
// else the cap's near corner (P − s, 0):
//   o* = P cos a + cos θm sin a − 1   or   (P − s) cos a.
// On the arc o(θ) = sin(θ − a) + cos θm sin a, monotone on the facing range θ − a ∈ [−π/2, π/2],
// so the arc is lit on [max(−θm, a − π/2), min(θm, a + asin(o* − cos θm sin a))], the gap on
// [s, min(s + d, o* / cos a)]. For a < 0 the mirror image y → P − y (θ → −θ) gives the bounds.
//
// The lit arc and gap project onto the line across the rays without overlap and cover it: their
// projected lengths add up to P cos a (checked in tests/models/test_poulin_fournier.cpp).
#include <algorithm>
#include <cmath>

#include "brdfkit/core/scalar_chain.h"
#include "brdfkit/core/vec.h"

namespace brdfkit {

template <class T> struct ProfileInterval {
  T lo, hi;
  bool empty() const { return !(value_of(hi) > value_of(lo)); }
};

// min / max by the scalar parts (a Jet keeps the derivative of the side chosen).
template <class T> T scalar_min(const T& a, const T& b) { return value_of(b) < value_of(a) ? b : a; }
template <class T> T scalar_max(const T& a, const T& b) { return value_of(b) > value_of(a) ? b : a; }

template <class T> ProfileInterval<T> overlap(const ProfileInterval<T>& x, const ProfileInterval<T>& y) {
  return {scalar_max(x.lo, y.lo), scalar_min(x.hi, y.hi)};
}

template <class T> struct CylinderProfile {
  T d, cos_m, theta_m, s, period;

  // Cap height h ∈ (0, 1], gap d ≥ 0.
  CylinderProfile(const T& h, const T& gap) : d(gap), cos_m(T(1) - h) {
    using std::acos;
    using std::sqrt;
    theta_m = acos(cos_m);
    s = sqrt(h * (T(2) - h));  // sin θm
    period = T(2) * s + d;
  }

  // The parts of the arc (θ) and of the gap (y) lit from angle a, |a| < π/2.
  struct Lit {
    ProfileInterval<T> arc, gap;
  };
  Lit lit(const T& a) const {
    if (value_of(a) >= 0) return lit_positive(a);
    const Lit m = lit_positive(-a);
    return {{-m.arc.hi, -m.arc.lo}, {period - m.gap.hi, period - m.gap.lo}};
  }

  // Projected lengths across the rays at angle a (they add up to P cos a): the lit arc's and gap's.
  T arc_projection(const T& a, const ProfileInterval<T>& arc) const {
    using std::sin;
    return arc.empty() ? T(0) : sin(arc.hi - a) - sin(arc.lo - a);
  }
  T gap_projection(const T& a, const ProfileInterval<T>& gap) const {
    using std::cos;
    return gap.empty() ? T(0) : (gap.hi - gap.lo) * cos(a);
  }

 private:
  Lit lit_positive(const T& a) const {
    using std::asin;
    using std::cos;
    using std::sin;
    const T ca = cos(a), sa = sin(a);
    const bool tangent = value_of(a) >= kPi / 2 - value_of(theta_m);
    const T o_star = tangent ? period * ca + cos_m * sa - T(1) : (period - s) * ca;
    const T rise = scalar_max(scalar_min(o_star - cos_m * sa, T(1)), T(-1));
    const ProfileInterval<T> arc{scalar_max(-theta_m, a - T(kPi / 2)), scalar_min(theta_m, a + asin(rise))};
    const ProfileInterval<T> gap{s, scalar_min(s + d, o_star / ca)};
    return {arc, gap};
  }
};

}  // namespace brdfkit
