#pragma once
// Cook-Torrance with an anisotropic distribution whose tangent lies at angle phi_t from the local
// frame's x axis (seed 002 §5 fits anisotropic materials with the lobe's orientation):
//   ρ(wi, wo) = kd/π + ks F(θd) D(h') G1(wi') G1(wo') / (4 cosθi cosθo)   (seed 004 Eq. 1),
// primes for directions in the lobe's frame (x' = the tangent), D and Λ of
// ndf/anisotropic_distribution.h, Schlick F, uncorrelated Smith masking as cook-torrance-<ndf>.
// Parameters: kd, ks (per channel, linear), alpha_x, alpha_y, phi_t, F0.
//
// phi_t's box: the lobe (αx, αy, φ) equals (αx, αy, φ + π) and (αy, αx, φ + π/2), so every lobe has
// an equal one with φ at least π/4 inside [−π/2, π/2]; the formula takes any angle.
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "brdfkit/core/param.h"
#include "brdfkit/core/turned_frame.h"
#include "brdfkit/core/vec.h"
#include "brdfkit/core/warp.h"
#include "brdfkit/fresnel/schlick.h"
#include "brdfkit/models/lobe_mixture.h"
#include "brdfkit/ndf/anisotropic_distribution.h"

namespace brdfkit {

template <template <class> class Ndf>
requires AnisotropicDistribution<Ndf>
struct CookTorranceAnisotropic {
  static constexpr bool kReciprocal = true;
  static constexpr int kNdf = 2, kPhi = 4, kF0 = 5;

  static std::string_view name() {
    static const std::string n = "cook-torrance-" + std::string(Ndf<double>::kName) + "-aniso";
    return n;
  }
  static std::string_view description() {
    static const std::string d = "kd/pi + ks F D G/(4 cos_i cos_o): anisotropic " + std::string(Ndf<double>::kTitle) +
                                 " D at tangent angle phi_t, Schlick F, uncorrelated Smith G";
    return d;
  }
  static ParamTable params() {
    ParamTable t = {
        {"kd", 0.0, 1.0, 0.2, Scope::PerChannel, true, "diffuse albedo of the Lambertian term kd/pi (DESIGN.md §6)"},
        {"ks", 0.0, 100.0, 0.5, Scope::PerChannel, true,
         "specular scale in ks F D G/(4 cos_i cos_o) (seed 004 Eq. 1)"}};
    for (auto& s : Ndf<double>::params()) t.push_back(s);
    ParamSpec phi{"phi_t",
                  -kPi / 2,
                  kPi / 2,
                  0.0,
                  Scope::Shared,
                  false,
                  "angle of the lobe's tangent (width alpha_x) from the local x axis, radians"};
    phi.domain_lower = -kUnbounded;
    phi.domain_upper = kUnbounded;
    t.push_back(phi);
    for (auto& s : SchlickFresnel<double>::params()) t.push_back(s);
    return t;
  }

  template <class T>
  static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    using std::sqrt;
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    const Ndf<T> ndf(p + kNdf);
    const TurnedFrame<T> lobe(p[kPhi]);
    const Vec3<T> i = lobe.to_local(wi), o = lobe.to_local(wo);
    const Vec3<T> sum = i + o;
    const T len = sqrt(sum.dot(sum));
    const Vec3<T> h = sum / len;
    const T cd = T(0.5) * len;  // |wi + wo| = 2 cos θd, symmetric in wi and wo
    const T g = T(1) / ((T(1) + ndf.Lambda(i)) * (T(1) + ndf.Lambda(o)));
    const T f = SchlickFresnel<T>(p + kF0).eval(cd);
    return p[0] * T(kInvPi) + p[1] * (f * ndf.D(h) * g / (T(4) * wi.z() * wo.z()));  // seed 004 Eq. 1
  }

  // Lobe selection as cook-torrance's: kd against ks F(cosθo) (seed 004 §5.5).
  static std::array<double, 2> lobe_probabilities(const double* p, const Vec3d& wo) {
    return lobes::selection_probabilities<2>({p[0], p[1] * SchlickFresnel<double>(p + kF0).eval(wo.z())});
  }
  // Diffuse: cosine hemisphere. Specular: m from D(m) m_z in the lobe's frame, turned back, wi the
  // mirror of wo about it.
  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double u_lobe) {
    if (!(wo.z() > 0)) return std::nullopt;
    if (lobes::pick(lobe_probabilities(p, wo), u_lobe) == 0) return square_to_cosine_hemisphere(u);
    const Vec3d m = TurnedFrame<double>(p[kPhi]).to_world(Ndf<double>(p + kNdf).sample(u));
    return lobes::reflect_about_half(wo, m);
  }
  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    if (!(wo.z() > 0 && wi.z() > 0)) return 0.0;
    const auto prob = lobe_probabilities(p, wo);
    const Ndf<double> ndf(p + kNdf);
    const TurnedFrame<double> lobe(p[kPhi]);
    const double spec = lobes::half_vector_pdf(wo, wi, [&](const Vec3d& h) { return ndf.pdf(lobe.to_local(h)); });
    return prob[0] * cosine_hemisphere_pdf(wi) + prob[1] * spec;
  }
};

}  // namespace brdfkit
