#pragma once
// Holzschuch & Pacanowski 2015's reflection + diffraction model (seed 004 Eq. 24–27; DESIGN.md
// §6), registered as `holzschuch-pacanowski`:
//   ρ(wi, wo) = kd/π + G(wi, wo) (ks D(θh) F(θd)/(4 cosθi cosθo) + kw/λ⁴ · Sz(f)/E_{a,λ}),
// with D the exponential power distribution (ndf/exponential_power.h, Eq. 26), F Schlick with
// per-channel F0 (fresnel/schlick.h, Eq. 27), the diffraction lobe Sz/E of
// models/hp_diffraction_lobe.h (Eq. 25, with the corrected E_{a,λ}: see there), λ the channel's
// wavelength (core/vec.h kChannelWavelengthUm, seed 004 §5.5) and G = G1(wi) G1(wo) (Eq. 7) from
// the §5.5 table of the exponential-power G1 (shadowing/exponential_power_g1.h), applied to both
// lobes (§5.3); the Fresnel term only on the reflection lobe (§5.3).
//
// Energy: with G = 1 the diffraction lobe reflects at most kw/λ⁴ (at normal incidence), the
// reflection lobe about ks F; nothing bounds kd + ks F + kw/λ⁴ by 1 (§5.5 asks k_T < 1 of the
// user), so the albedo exceeds 1 where the colours do (kw > λ⁴ alone suffices: λ⁴ = 0.173,
// 0.077, 0.039 for R, G, B).
//
// Sampling (§5.5): three lobes picked with probability proportional to an albedo estimate each,
// ks F(cosθo) for the reflection lobe, kw/λ⁴ for the diffraction lobe, kd for the diffuse one
// (§5.5 writes k_s, k_w, k_d; kw enters ρ divided by λ⁴, so kw/λ⁴ is the diffraction lobe's
// albedo). The reflection lobe samples h from D cosθh (ExponentialPower::sample: Eq. 22–23
// with the exponent 1/(2p), not the printed p/2; DESIGN.md §6) and reflects wo about it; the
// diffraction lobe is sampled as a diffuse lobe (§5.1); the density is the mixture's (§5.5:
// "divide by the sum of the PDFs").
#include <array>
#include <cmath>
#include <optional>
#include <string_view>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/warp.h"
#include "brdfkit/fresnel/schlick.h"
#include "brdfkit/models/hp_diffraction_lobe.h"
#include "brdfkit/models/lobe_mixture.h"
#include "brdfkit/models/model.h"
#include "brdfkit/core/param.h"
#include "brdfkit/ndf/exponential_power.h"
#include "brdfkit/shadowing/exponential_power_g1.h"

namespace brdfkit {

struct HolzschuchPacanowski {
  static std::string_view name() { return "holzschuch-pacanowski"; }
  static std::string_view description() {
    return "kd/pi + G (ks D F/(4 cos_i cos_o) + kw/lambda^4 Sz(f)/E): exponential power D, Schlick F, diffraction "
           "lobe (Holzschuch-Pacanowski 2015)";
  }
  static constexpr bool kReciprocal = true;
  template <class T> using Distribution = ExponentialPower<T>;
  // Layout of p: kd, ks, kw, then σ, p (ExponentialPower(p + 3)), a, F0.
  static constexpr int kNdfOffset = 3;
  static constexpr int kA = 5;
  static constexpr int kFresnelOffset = 6;

  static ParamTable params() {
    // Bounds: p ≤ 5 and F0 ∈ [0.02, 1.2] are the fitting constraints of seed 004 §5.8 (its G1
    // table covers p ∈ [0.1, 5]); a as in §5.7 (fits 0.3–1.4 µm⁻¹) with room on both sides.
    return {{"kd", 0.0, 1.0, 0.2, Scope::PerChannel, true, "diffuse albedo (kd/pi, seed 004 Eq. 24)"},
            {"ks", 0.0, 10.0, 0.5, Scope::PerChannel, true, "reflection lobe colour (seed 004 Eq. 24)"},
            {"kw", 0.0, 1.0, 0.01, Scope::PerChannel, true,
             "diffraction lobe colour; kw/lambda^4 is its albedo at normal incidence (seed 004 Eq. 24)"},
            {"sigma", 1e-4, 2.0, 0.1, Scope::Shared, false, "exponential power slope scale (seed 004 Eq. 26)"},
            {"p", ExponentialPowerG1Table::kPMin, ExponentialPowerG1Table::kPMax, 0.6, Scope::Shared, false,
             "exponential power shape; 1 is Beckmann (seed 004 Eq. 26, bound 5 of section 5.8)"},
            {"a", 0.01, 100.0, 1.0, Scope::Shared, false, "diffraction spatial frequency in 1/um (seed 004 Eq. 25)"},
            {"F0", 0.02, 1.2, 0.04, Scope::PerChannel, false,
             "Schlick Fresnel at normal incidence (seed 004 Eq. 27, bounds of section 5.8)"}};
  }

  static double wavelength(int c) { return kChannelWavelengthUm[c < 0 ? 0 : (c > 2 ? 2 : c)]; }

  // σ tanθ, the argument of the §5.5 G1 table; 0 at the normal.
  template <class T> static T slope_scale(const T& sigma, const T& cos_theta) {
    using std::sqrt;
    const T s2 = T(1) - cos_theta * cos_theta;
    if (!(s2 > T(0))) return T(0);  // normal direction: no masking (and no 0/0 in a Jet's sqrt)
    return sigma * sqrt(s2) / cos_theta;
  }
  // G1 of seed 004 §5.5.
  template <class T> static T g1(const T& sigma, const T& p, const T& cos_theta) {
    return ExponentialPowerG1Table::instance().g1(slope_scale(sigma, cos_theta), p);
  }

  template <class T> static T eval(const T* p, int c, const Vec3<T>& wi, const Vec3<T>& wo) {
    using std::sqrt;
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    const ExponentialPower<T> ndf(p + kNdfOffset);
    const Vec3<T> s = wi + wo;
    const T len = sqrt(s.dot(s));
    // |wi + wo| = 2 cosθd: one root for θh and θd, symmetric in (wi, wo).
    const T cos_h = s.z() / len, cos_d = T(0.5) * len;
    const T g = g1(ndf.sigma, ndf.p, wi.z()) * g1(ndf.sigma, ndf.p, wo.z());  // seed 004 Eq. 7
    return eval_with(p, c, wi, wo, cos_d, ndf.D(cos_h), g);
  }

  // eval's values at n pairs within 1e-12 relative: the distribution (whose normalization costs a
  // long-double Γ(1/p)) built once per batch, and D and the G1 table's coordinate computed a block
  // of pairs at a time with vector math (ndf/d_block.h), where eval calls libm's pow and exp three
  // times per pair.
  static void eval_batch(const double* p, int c, size_t n, const double* wi_x, const double* wi_y,
                         const double* wi_z, const double* wo_x, const double* wo_y, const double* wo_z,
                         double* out);
  // eval_batch of the three channels (Model::eval_batch_rgb): D and G1 once for R, G and B where
  // they share σ and p, each output equal to its channel's eval_batch to the bit.
  static void eval_batch_rgb(const double* const p[3], size_t n, const double* wi_x, const double* wi_y,
                             const double* wi_z, const double* wo_x, const double* wo_y, const double* wo_z,
                             double* const out[3]);

  // ρ of Eq. 24 from D(θh), cosθd and G = G1(wi) G1(wo), for directions above the horizon.
  template <class T>
  static T eval_with(const T* p, int c, const Vec3<T>& wi, const Vec3<T>& wo, const T& cos_d, const T& d,
                     const T& g) {
    const double lambda = wavelength(c);
    const T reflection = p[1] * d * SchlickFresnel<T>(p + kFresnelOffset).eval(cos_d) / (T(4) * wi.z() * wo.z());
    const T lambda4 = T(lambda * lambda * lambda * lambda);
    const T diffraction = p[2] / lambda4 * HpDiffractionLobe<T>{p[kA], lambda}.eval(wi, wo);
    return p[0] * T(kInvPi) + g * (reflection + diffraction);  // seed 004 Eq. 24
  }

  // Lobe probabilities {reflection, diffraction, diffuse} (see the header comment).
  static std::array<double, 3> probabilities(const double* p, int c, const Vec3d& wo) {
    const double lambda = wavelength(c);
    const double f = SchlickFresnel<double>(p + kFresnelOffset).eval(wo.z());
    return lobes::selection_probabilities<3>({p[1] * f, p[2] / (lambda * lambda * lambda * lambda), p[0]});
  }

  static std::optional<Vec3d> sample(const double* p, int c, const Vec3d& wo, const Vec2d& u, double u_lobe) {
    if (!(wo.z() > 0)) return std::nullopt;
    if (lobes::pick(probabilities(p, c, wo), u_lobe) == 0)
      return lobes::reflect_about_half(wo, ExponentialPower<double>(p + kNdfOffset).sample(u));
    const Vec3d wi = square_to_cosine_hemisphere(u);  // diffuse, and diffraction (§5.1)
    if (!(wi.z() > 0)) return std::nullopt;
    return wi;
  }

  static double pdf(const double* p, int c, const Vec3d& wo, const Vec3d& wi) {
    if (!(wi.z() > 0 && wo.z() > 0)) return 0.0;
    const auto prob = probabilities(p, c, wo);
    const ExponentialPower<double> ndf(p + kNdfOffset);
    const double reflection = lobes::half_vector_pdf(wo, wi, [&](const Vec3d& h) { return ndf.pdf(h); });
    return prob[0] * reflection + (prob[1] + prob[2]) * cosine_hemisphere_pdf(wi);
  }
};

// The registered runtime instance (holzschuch_pacanowski.cpp); it exposes D to `brdfkit check`.
const Model* holzschuch_pacanowski_model();

}  // namespace brdfkit
