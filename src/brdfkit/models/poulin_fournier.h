#pragma once
// Poulin & Fournier 1990's anisotropic surface of parallel cylinders, in seed 002's form (§5,
// Fig. 9: parameters n, d, h; M = kd·diffuse + ks·specular):
//   ρ(wi, wo) = kd/π + ks/(P cosθi cosθo) ∫ f_e(N) (N·wi)(N·wo) V(wi) V(wo) dℓ,
// the single-scattering BRDF of the cross-section profile of models/cylinder_profile.h (the
// reflectance of an explicit microsurface, the integral Ashikhmin et al. 2000 start from before
// they make the surface statistical): ℓ runs over one period P, V is 1 where the element is lit
// (seen), and each element reflects Phong's lobe, PF 1990's per-element specular term, in its
// normalized form
//   f_e(N) = (n + 2)/(2π) max(0, R·wo)ⁿ,  R = wi mirrored about N
// (Lewis 1994: ks is then an element's albedo at normal incidence). With N = (0, sin θ, cos θ) in
// the lobe's frame, R·wo = 2 (N·wi)(N·wo) − wi·wo = A cos 2(θ − θ*) − B, A = |wi⊥||wo⊥|,
// B = wi_x wo_x (x along the axis, ⊥ the cross-section components), θ* the mean of the two
// directions' cross-section angles: one peak of width ≈ sqrt((A − B)/(4nA)) in θ, integrated by
// core/peaked_quadrature.h. On the flat gap the integrand is constant. The Lambertian term is
// seed 002's common diffuse term (§3.1), not PF's diffuse cylinders.
// Parameters: kd, ks (per channel, linear), n, d, h (PF's exponent, gap and height, radius 1),
// phi_t (the cylinders' axis from the local x axis; φ and φ + π are the same surface).
// Reciprocal: the integrand and V(wi) V(wo) are symmetric in wi and wo.
//
// Sampling: kd against ks; the specular draw picks an element seen from wo with probability
// proportional to its projected length (N·wo, the visible-normal idea of Heitz & d'Eon 2014 on an
// explicit profile: the seen parts project onto P cos a without overlap), then wi from the
// cosine-power lobe about wo mirrored there; the density integrates the same profile.
#include <array>
#include <cmath>
#include <optional>
#include <string_view>

#include "brdfkit/core/param.h"
#include "brdfkit/core/peaked_quadrature.h"
#include "brdfkit/core/turned_frame.h"
#include "brdfkit/core/vec.h"
#include "brdfkit/core/warp.h"
#include "brdfkit/models/cylinder_profile.h"
#include "brdfkit/models/lobe_mixture.h"

namespace brdfkit {

struct PoulinFournier {
  static constexpr bool kReciprocal = true;
  static constexpr int kN = 2, kD = 3, kH = 4, kPhi = 5;

  static std::string_view name() { return "poulin-fournier"; }
  static std::string_view description() {
    return "kd/pi + ks x parallel cylinders (gap d, height h) of Phong elements cos^n, shadowed and masked "
           "(Poulin-Fournier 1990)";
  }
  static ParamTable params() {
    ParamSpec phi{"phi_t", -kPi / 2, kPi / 2, 0.0, Scope::Shared, false,
                  "angle of the cylinders' axis from the local x axis, radians"};
    phi.domain_lower = -kUnbounded;
    phi.domain_upper = kUnbounded;
    return {{"kd", 0.0, 1.0, 0.2, Scope::PerChannel, true, "diffuse albedo (Lambertian kd/pi, seed 002 3.1)"},
            {"ks", 0.0, 1.0, 0.5, Scope::PerChannel, true, "albedo of a cylinder element at normal incidence"},
            {"n", 1.0, 1e4, 30.0, Scope::Shared, false, "Phong exponent of an element (Poulin-Fournier 1990)", 0.01,
             kUnbounded},
            {"d", 0.0, 4.0, 0.5, Scope::Shared, false, "gap between neighbouring cylinders, in radii (PF 1990)", 0.0,
             kUnbounded},
            {"h", 0.05, 1.0, 0.5, Scope::Shared, false, "height of the cylinders above the base, in radii (PF 1990)",
             1e-3, 1.0},
            phi};
  }

  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    return p[0] * T(kInvPi) + p[1] * specular(p, wi, wo);
  }

  // ∫ f_e (N·wi)(N·wo) V V dℓ / (P cosθi cosθo): the ks = 1 lobe.
  template <class T> static T specular(const T* p, const Vec3<T>& wi, const Vec3<T>& wo) {
    const TurnedFrame<T> lobe(p[kPhi]);
    const Vec3<T> i = lobe.to_local(wi), o = lobe.to_local(wo);
    const CylinderProfile<T> profile(p[kH], p[kD]);
    const auto lit = profile.lit(angle(i)), seen = profile.lit(angle(o));
    const T sum = profile_integral(p[kN], i, o, overlap(lit.arc, seen.arc), overlap(lit.gap, seen.gap),
                                   [](const T& ni, const T& no) { return ni * no; });
    return (p[kN] + T(2)) * T(0.5 * kInvPi) * sum / (profile.period * wi.z() * wo.z());
  }

  static std::array<double, 2> lobe_probabilities(const double* p) {
    return lobes::selection_probabilities<2>({p[0], p[1]});
  }

  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double u_lobe) {
    if (!(wo.z() > 0)) return std::nullopt;
    const auto prob = lobe_probabilities(p);
    if (lobes::pick(prob, u_lobe) == 0) return square_to_cosine_hemisphere(u);
    const TurnedFrame<double> lobe(p[kPhi]);
    const Vec3d o = lobe.to_local(wo);
    const Vec3d n = seen_normal(p, o, std::clamp((u_lobe - prob[0]) / prob[1], 0.0, 1.0));
    const Vec3d wi = lobe.to_world(frame_around(reflect(o, n)) * lobes::sample_cosine_power(p[kN], u));
    if (!(wi.z() > 0)) return std::nullopt;
    return wi;
  }

  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    if (!(wo.z() > 0 && wi.z() > 0)) return 0.0;
    const auto prob = lobe_probabilities(p);
    const TurnedFrame<double> lobe(p[kPhi]);
    const Vec3d i = lobe.to_local(wi), o = lobe.to_local(wo);
    const CylinderProfile<double> profile(p[kH], p[kD]);
    const double a = angle(o);
    const auto seen = profile.lit(a);
    // An element's probability is its projected length over the seen total, |wo⊥| cos(θ − a) dθ
    // = (N·wo) dθ on the arc, wo_z dy on the gap, over |wo⊥| (arc + gap projections).
    const double total = std::hypot(o.y(), o.z()) *
                         (profile.arc_projection(a, seen.arc) + profile.gap_projection(a, seen.gap));
    const double sum = profile_integral(p[kN], i, o, seen.arc, seen.gap, [](double, double no) { return no; });
    return prob[0] * cosine_hemisphere_pdf(wi) + prob[1] * (p[kN] + 1) * 0.5 * kInvPi * sum / total;
  }

 private:
  // A direction's angle in the cross-section, from z towards y (|a| < π/2 above the horizon).
  template <class T> static T angle(const Vec3<T>& w) {
    using std::atan2;
    return atan2(w.y(), w.z());
  }

  // ∫ max(0, R·wo)ⁿ weight(N·wi, N·wo) over the arc interval (dθ) and the gap interval (dy).
  template <class T, class Weight>
  static T profile_integral(const T& n, const Vec3<T>& i, const Vec3<T>& o, const ProfileInterval<T>& arc,
                            const ProfileInterval<T>& gap, const Weight& weight) {
    using std::acos;
    using std::pow;
    using std::sqrt;
    const T cos_io = i.dot(o);
    auto at = [&](const T& ni, const T& no) {
      const T r = T(2) * ni * no - cos_io;
      return value_of(r) > 0 ? pow(r, n) * weight(ni, no) : T(0);
    };
    T sum(0);
    if (!gap.empty()) sum += (gap.hi - gap.lo) * at(i.z(), o.z());
    // R·wo = A cos 2(θ − θ*) − B is positive for |θ − θ*| < acos(B/A)/2.
    const T a = sqrt((i.y() * i.y() + i.z() * i.z()) * (o.y() * o.y() + o.z() * o.z())), b = i.x() * o.x();
    if (!(value_of(a) > value_of(b)) || arc.empty()) return sum;
    const T peak = T(0.5) * (angle(i) + angle(o));
    const T reach = T(0.5) * acos(scalar_max(b / a, T(-1)));
    const ProfileInterval<T> lobe = overlap(arc, ProfileInterval<T>{peak - reach, peak + reach});
    const double width = std::sqrt(value_of((a - b) / (T(4) * n * a)));
    auto f = [&](const T& theta) {
      using std::cos;
      using std::sin;
      const T st = sin(theta), ct = cos(theta);
      return at(i.y() * st + i.z() * ct, o.y() * st + o.z() * ct);
    };
    return sum + integrate_peaked<T>(f, lobe.lo, lobe.hi, peak, width);
  }

  // The normal of the element seen from o (lobe frame) at fraction x of the seen projected length.
  static Vec3d seen_normal(const double* p, const Vec3d& o, double x) {
    const CylinderProfile<double> profile(p[kH], p[kD]);
    const double a = angle(o);
    const auto seen = profile.lit(a);
    const double arc = profile.arc_projection(a, seen.arc), gap = profile.gap_projection(a, seen.gap);
    const double t = x * (arc + gap);
    if (!(t < arc)) return Vec3d(0, 0, 1);
    const double theta = a + std::asin(std::clamp(std::sin(seen.arc.lo - a) + t, -1.0, 1.0));
    return Vec3d(0, std::sin(theta), std::cos(theta));
  }
};

}  // namespace brdfkit
