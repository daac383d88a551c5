#pragma once
// The classic lobes of seed 002 as DESIGN.md §6 writes them, transcribed for the reference tests
// (test_ward_reference.cpp, test_phong_family_reference.cpp, test_lobe_sum_reference.cpp): each
// without its colour, with its normalization constant as a parameter so the tests can show that
// a 5 % error in it fails.
#include <algorithm>
#include <cmath>

#include "brdfkit/core/vec.h"
#include "reference_math.h"

namespace brdfkit::test::ref {

// Ward 1992 Eq. 5a (DESIGN.md §6), anisotropic; αx = αy is `ward`; `duer` puts Dür 2006's
// cosθi cosθo in place of sqrt(cosθi cosθo). 4π is the paper's normalization.
constexpr double kWardNorm = 4 * kPi;

inline double ward_aniso_lobe(const Vec3d& wi, const Vec3d& wo, double ax, double ay, bool duer, double norm = kWardNorm) {
  const Vec3d h = (wi + wo).normalized();
  const double theta_h = std::acos(h.z()), phi_h = std::atan2(h.y(), h.x());
  const double tan2 = sqr(std::tan(theta_h));
  const double e = tan2 * (sqr(std::cos(phi_h) / ax) + sqr(std::sin(phi_h) / ay));
  const double cos_term = duer ? wi.z() * wo.z() : std::sqrt(wi.z() * wo.z());
  return std::exp(-e) / (norm * ax * ay * cos_term);
}

constexpr double kBlinnPhongNorm = 8 * kPi;    // (N+2)/(8π)
constexpr double kLafortuneNorm = 2 * kPi;     // (N+2)/(2π)
constexpr double kAshikhminNorm = 8 * kPi;     // sqrt((nu+1)(nv+1))/(8π)

// brdfkit's Blinn-Phong constant (N+2)/(8π) (DESIGN.md §6).
inline double blinn_phong_lobe(const Vec3d& wi, const Vec3d& wo, double n, double norm = kBlinnPhongNorm) {
  return (n + 2) / norm * std::pow((wi + wo).normalized().z(), n);
}
// Lafortune 1997 Eq. 6 with Ngan's normalization (DESIGN.md §6); u = wi, v = wo.
inline double lafortune_lobe(const Vec3d& u, const Vec3d& v, double cxy, double cz, double n, double norm = kLafortuneNorm) {
  const double dot = cxy * (u.x() * v.x() + u.y() * v.y()) + cz * u.z() * v.z();
  if (!(dot > 0)) return 0.0;
  return (n + 2) / (norm * std::pow(std::max(std::abs(cxy), std::abs(cz)), n)) * std::pow(dot, n);
}
// Ashikhmin & Shirley 2000 Eq. 4 without its Fresnel factor; k1 = wi, k2 = wo.
inline double ashikhmin_lobe(const Vec3d& k1, const Vec3d& k2, double nu, double nv, double norm = kAshikhminNorm) {
  const Vec3d h = (k1 + k2).normalized();
  const double phi_h = std::atan2(h.y(), h.x());
  const double e = nu * sqr(std::cos(phi_h)) + nv * sqr(std::sin(phi_h));
  return std::sqrt((nu + 1) * (nv + 1)) / norm * std::pow(h.z(), e) / (h.dot(k1) * std::max(k1.z(), k2.z()));
}

}  // namespace brdfkit::test::ref
