#pragma once
// What an anisotropic microfacet distribution of ndf/ is: the isotropic interface of
// ndf/distribution.h with directions in place of angles, in the lobe's own frame (x = the lobe's
// tangent, the direction of width alpha_x; models/cook_torrance_anisotropic.h rotates into it):
//   static constexpr std::string_view kName, kTitle;   "ggx", "GGX": the catalogue's names
//   static ParamTable params();                         alpha_x, alpha_y (Scope::Shared)
//   explicit X(const T* p);                             from parameter values in params() order
//   T D(const Vec3<T>& m) const;                        normalized: ∫ D(m) m_z dω = 1, 0 for m_z ≤ 0
//   T Lambda(const Vec3<T>& w) const;                   Smith Λ of unit direction w (w_z > 0)
//   Vec3d sample(const Vec2d& u) const;                 m with density D(m) m_z
//   double pdf(const Vec3d& m) const;                   = D(m) m_z
// Both families are stretched isotropic ones (Heitz 2014, "Understanding the masking-shadowing
// function", its section on anisotropic distributions): slopes (x/αx, y/αy) of the unit-width
// distribution, so sampling draws the unit-width slope and stretches it, and Λ is the isotropic Λ
// at the projected width α(φ) = sqrt(cos²φ αx² + sin²φ αy²).
#include <concepts>
#include <string_view>

#include "brdfkit/core/param.h"
#include "brdfkit/core/vec.h"

namespace brdfkit {

// (αx ωx, αy ωy) / ωz: the direction's stretched slope, whose length is α(φ) tanθ (Heitz 2014, anisotropic Λ).
template <class T>
T stretched_tan2(const Vec3<T>& w, const T& ax, const T& ay) {
  const T x = ax * w.x(), y = ay * w.y();
  return (x * x + y * y) / (w.z() * w.z());
}

// The microfacet normal of slope (sx, sy): m ∝ (−sx, −sy, 1).
inline Vec3d normal_of_slope(double sx, double sy) { return Vec3d(-sx, -sy, 1.0).normalized(); }

template <template <class> class Ndf>
concept AnisotropicDistribution = requires(const Ndf<double>& d, const double* p, const Vec3d& m, const Vec2d& u) {
  { Ndf<double>::kName } -> std::convertible_to<std::string_view>;
  { Ndf<double>::params() } -> std::same_as<ParamTable>;
  Ndf<double>(p);
  { d.D(m) } -> std::same_as<double>;
  { d.Lambda(m) } -> std::same_as<double>;
  { d.sample(u) } -> std::same_as<Vec3d>;
  { d.pdf(m) } -> std::same_as<double>;
};

}  // namespace brdfkit
