#pragma once
// Fresnel and masking terms written out for the reference tests (not brdfkit's fresnel/ or
// shadowing/ code): each in its textbook form, so a transcription slip in brdfkit shows.
#include <algorithm>
#include <cmath>
#include <complex>

#include "brdfkit/core/vec.h"

namespace brdfkit::test::ref {

// Schlick 1994: F0 + (1 − F0)(1 − cos θd)⁵ (DESIGN.md §5).
inline double schlick(double f0, double cos_d) { return f0 + (1 - f0) * std::pow(1 - std::clamp(cos_d, 0.0, 1.0), 5); }

// Unpolarized Fresnel reflectance of a complex index η + ik seen from air: Snell's law and the
// amplitude coefficients r⊥, r∥ in complex arithmetic (Born & Wolf §1.5; pbrt-v4
// src/pbrt/util/scattering.h FrComplex). k = 0 is a dielectric, where it equals Cook & Torrance
// 1982's closed form (DESIGN.md §5).
inline double fresnel_complex(double cos_i, double eta, double k) {
  using C = std::complex<double>;
  cos_i = std::clamp(cos_i, 0.0, 1.0);
  const C n(eta, k);
  const C sin2_t = (1 - cos_i * cos_i) / (n * n);
  const C cos_t = std::sqrt(C(1) - sin2_t);
  const C r_perp = (cos_i - n * cos_t) / (cos_i + n * cos_t);
  const C r_parl = (n * cos_i - cos_t) / (n * cos_i + cos_t);
  return 0.5 * (std::norm(r_perp) + std::norm(r_parl));
}
inline double fresnel_dielectric(double cos_i, double eta) { return fresnel_complex(cos_i, eta, 0.0); }

// Cook & Torrance 1982's V-groove masking-shadowing (DESIGN.md §4):
// min(1, 2 cosθh cosθo / (wo·h), 2 cosθh cosθi / (wo·h)).
inline double v_groove(const Vec3d& wi, const Vec3d& wo) {
  const Vec3d h = (wi + wo).normalized();
  const double oh = wo.dot(h);
  return std::min({1.0, 2 * h.z() * wo.z() / oh, 2 * h.z() * wi.z() / oh});
}

}  // namespace brdfkit::test::ref
