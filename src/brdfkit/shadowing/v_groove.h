#pragma once
// Cook-Torrance V-groove shadowing/masking (Torrance & Sparrow 1967, Cook & Torrance 1982;
// DESIGN.md §4, seed 003 Eq. 15): G = min(1, 2 cosθh cosθo / (wo·h), 2 cosθh cosθi / (wo·h)),
// with h = normalize(wi + wo); wo·h = wi·h, so G is symmetric in (wi, wo) (reciprocal).
#include "brdfkit/core/vec.h"

namespace brdfkit {

// G for unit directions wi, wo in the local frame (n = +z); 0 when either is below the horizon.
template <class T> T v_groove_g(const Vec3<T>& wi, const Vec3<T>& wo) {
  if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
  const Vec3<T> s = wi + wo;
  const T len = s.norm();
  if (!(len > T(0))) return T(0);
  const Vec3<T> h = s / len;
  // wo·h = wi·h analytically; their mean keeps G exactly symmetric in floating point.
  const T oh = T(0.5) * s.dot(h);
  if (!(oh > T(0))) return T(0);
  const T k = T(2) * h.z() / oh;
  const T go = k * wo.z();
  const T gi = k * wi.z();
  T g = go < gi ? go : gi;
  return g < T(1) ? g : T(1);
}

}  // namespace brdfkit
