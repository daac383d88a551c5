#pragma once
// Löw et al. 2012 smooth-surface model (seed 003 §3.2; DESIGN.md §6):
//   low-smooth    ρ = kd/π + F(θd′; η) · A / (1 + B‖Dp‖²)^C                  (seed 003 Eq. 11–12)
//   low-smooth-2  ρ = kd/π + S1(‖Dp‖) + F(θd′; η) S2(‖Dp‖), Sⱼ = Aⱼ/(1 + Bⱼ‖Dp‖²)^Cⱼ  (Eq. 34)
// Dp = Lp + Vp, the tangent-plane parts of wi and wo (Eq. 9–10: the unnormalized half vector
// minus its normal part); cos θd′ = sqrt(1 − ‖Lp − Vp‖²/4) (Eq. 13–14); F is the
// Cook-Torrance dielectric Fresnel with index η (extinction 0); the obliquity factor G′ = 1.
// Reciprocal: Dp and ‖Lp − Vp‖ are symmetric in (wi, wo).
//
// Sampling (seed 003 Eq. 17–22): Lp is drawn on the unit disk with the density
// Pd(x) = M / (1 + B‖x + Vp‖²), i.e. the ABC lobe with C = 1 (the paper's proxy for any C),
// and wi = (x, sqrt(1 − ‖x‖²)); the disk's area measure carries cosθi, so the solid-angle
// density is Pd · cosθi (Eq. 17). Derived here in closed form (the OCR of Eq. 19–22 is garbled):
//   1/M = ∫disk dA/(1 + B‖x + v‖²) = (π/B) L,
//   L = ln(1 + B(1 − r_o²) + sqrt(1 + 2B(1 + r_o²) + B²(1 − r_o²)²)) − ln 2   (Eq. 19)
//   radius: r² = expm1(ξ₁L) (1 + B r_o² e^{−ξ₁L}) / B   (Eq. 20 with E = 2 e^{ξ₁L}, Eq. 22)
//   angle about −Vp: ψ = 2 atan( sqrt((a−b)/(a+b)) tan(π(ξ₂ − ½)) ), a = 1 + B(r² + r_o²),
//   b = 2B r r_o (inverts ∫ dψ/(a − b cos ψ); Eq. 21 measures the angle from the mirror side).
// Every draw lands on the hemisphere, so the density integrates to exactly 1.
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "brdfkit/core/warp.h"
#include "brdfkit/fresnel/dielectric.h"
#include "brdfkit/models/lobe_mixture.h"
#include "brdfkit/core/param.h"

namespace brdfkit {

namespace low_smooth_detail {

// ‖Dp‖² and cos θd′ (seed 003 Eq. 10, 14).
template <class T> void projected(const Vec3<T>& wi, const Vec3<T>& wo, T& dp2, T& cos_dp) {
  using std::sqrt;
  const T sx = wi.x() + wo.x(), sy = wi.y() + wo.y();
  const T dx = wi.x() - wo.x(), dy = wi.y() - wo.y();
  dp2 = sx * sx + sy * sy;
  const T c2 = T(1) - (dx * dx + dy * dy) / T(4);
  cos_dp = c2 > T(0) ? sqrt(c2) : T(0);
}

// The ABC function A/(1 + B x²)^C of seed 003 Eq. 11, with x² = ‖Dp‖².
template <class T> T abc(const T& a, const T& b, const T& c, const T& dp2) {
  using std::pow;
  return a * pow(T(1) + b * dp2, -c);
}

// ∫ over the unit disk of A/(1 + Bρ²)^C about its centre: a lobe-albedo estimate used only to
// choose lobes (any positive estimate keeps sampling unbiased).
inline double abc_albedo_estimate(double a, double b, double c) {
  if (!(a > 0 && b > 0)) return std::max(a, 0.0) * kPi;
  const double l = std::log1p(b);
  const double x = (1.0 - c) * l;
  const double g = std::abs(x) < 1e-8 ? l * (1 + x / 2) : std::expm1(x) / (1.0 - c);
  return a * kPi / b * g;
}

// Seed 003 Eq. 17–22 for one B and one wo (see the header comment).
struct DiskSampler {
  double b;
  Vec2d v;     // Vp
  double ro2;  // ‖Vp‖²
  double l;    // L of Eq. 19

  DiskSampler(double b_, const Vec3d& wo) : b(b_), v(wo.x(), wo.y()), ro2(v.squaredNorm()) {
    const double q1m1 = 2 * b * (1 + ro2) + b * b * (1 - ro2) * (1 - ro2);  // Q(1) − 1
    const double sqrt_q1_m1 = q1m1 / (std::sqrt(1 + q1m1) + 1);               // sqrt(Q(1)) − 1, no cancellation
    l = std::log1p((b * (1 - ro2) + sqrt_q1_m1) / 2);
  }
  // Area of the disk under 1/(1 + B‖x + v‖²): (π/B) L, → π as B → 0.
  double integral() const { return b > 0 ? kPi * l / b : kPi; }

  std::optional<Vec3d> sample(const Vec2d& u) const {
    const double t = u.x() * l;
    double s = b > 0 ? std::expm1(t) * (1 + b * ro2 * std::exp(-t)) / b : u.x();
    s = std::clamp(s, 0.0, 1.0);
    const double r = std::sqrt(s), ro = std::sqrt(ro2);
    const double amb = 1 + b * (r - ro) * (r - ro), apb = 1 + b * (r + ro) * (r + ro);
    const double psi = 2 * std::atan(std::sqrt(amb / apb) * std::tan(kPi * (u.y() - 0.5)));
    const double phi = (ro2 > 0 ? std::atan2(-v.y(), -v.x()) : 0.0) + psi;
    const double z = std::sqrt(std::max(0.0, 1 - s));
    if (!(z > 0)) return std::nullopt;
    return Vec3d(r * std::cos(phi), r * std::sin(phi), z);
  }
  double pdf(const Vec3d& wi) const {
    if (!(wi.z() > 0)) return 0.0;
    const double dx = wi.x() + v.x(), dy = wi.y() + v.y();
    return wi.z() / (integral() * (1 + b * (dx * dx + dy * dy)));  // Eq. 17–18
  }
};

}  // namespace low_smooth_detail

struct LowSmooth {
  static std::string_view name() { return "low-smooth"; }
  static std::string_view description() {
    return "Lambert + Low 2012 smooth-surface model, F(theta_d'; eta) A/(1 + B |Dp|^2)^C";
  }
  static constexpr bool kReciprocal = true;
  static ParamTable params() {
    // Löw's published fits span A ∈ [0.25, 2343], B ∈ [6.6, 4.5e6], C ∈ [0.014, 2.24], η ∈ [1.05, 9.1]
    // (published-fits/low2012-smooth-E2.json); the paper mentions B up to 10⁸.
    return {{"kd", 0.0, 1.0, 0.5, Scope::PerChannel, true, "diffuse albedo (Lambertian Kd/pi, seed 003 Eq. 12)"},
            {"A", 0.0, 1e4, 1.0, Scope::PerChannel, true, "ABC scale A = a^2 (seed 003 Eq. 11)"},
            {"B", 1e-3, 1e9, 1000.0, Scope::Shared, false, "ABC sharpness B = b^2 (seed 003 Eq. 11)"},
            {"C", 1e-3, 5.0, 1.0, Scope::Shared, false, "ABC fall-off C = (c+1)/2 (seed 003 Eq. 11)"},
            {"eta", 1.0, 100.0, 1.5, Scope::Shared, false, "Fresnel parameter eta (Cook-Torrance dielectric, seed 003 3.2)",
             1.0, kUnbounded}};
  }
  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    T dp2, cos_dp;
    low_smooth_detail::projected(wi, wo, dp2, cos_dp);
    // seed 003 Eq. 12 with G′ = 1, Q′ = F(θd′; η).
    return p[0] * T(kInvPi) + DielectricFresnel<T>(p + 4).eval(cos_dp) * low_smooth_detail::abc(p[1], p[2], p[3], dp2);
  }
  static std::array<double, 2> probabilities(const double* p, const Vec3d& wo) {
    // At the mirror direction cos θd′ = cos θo.
    const double spec = DielectricFresnel<double>(p + 4).eval(wo.z()) * low_smooth_detail::abc_albedo_estimate(p[1], p[2], p[3]);
    return lobes::selection_probabilities<2>({p[0], spec});
  }
  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double u_lobe) {
    if (lobes::pick(probabilities(p, wo), u_lobe) == 0) return square_to_cosine_hemisphere(u);
    return low_smooth_detail::DiskSampler(p[2], wo).sample(u);
  }
  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    if (!(wi.z() > 0 && wo.z() > 0)) return 0.0;
    const auto prob = probabilities(p, wo);
    return prob[0] * cosine_hemisphere_pdf(wi) + prob[1] * low_smooth_detail::DiskSampler(p[2], wo).pdf(wi);
  }
};

struct LowSmooth2 {
  static std::string_view name() { return "low-smooth-2"; }
  static std::string_view description() {
    return "Lambert + Low 2012 two-lobe smooth-surface model, S1(|Dp|) + F(theta_d'; eta) S2(|Dp|)";
  }
  static constexpr bool kReciprocal = true;
  static ParamTable params() {
    ParamTable t{{"kd", 0.0, 1.0, 0.5, Scope::PerChannel, true, "diffuse albedo (Lambertian Kd/pi, seed 003 Eq. 34)"}};
    for (int j = 1; j <= 2; ++j) {
      const std::string s = std::to_string(j);
      const std::string which = j == 1 ? "wide lobe without Fresnel" : "lobe with Fresnel";
      t.push_back({"A" + s, 0.0, 1e4, j == 1 ? 0.1 : 1.0, Scope::PerChannel, true, "ABC scale, " + which + " (seed 003 Eq. 34)"});
      t.push_back({"B" + s, 1e-3, 1e9, j == 1 ? 10.0 : 1000.0, Scope::Shared, false, "ABC sharpness, " + which + " (seed 003 Eq. 34)"});
      t.push_back({"C" + s, 1e-3, 5.0, 1.0, Scope::Shared, false, "ABC fall-off, " + which + " (seed 003 Eq. 34)"});
    }
    t.push_back({"eta", 1.0, 100.0, 1.5, Scope::Shared, false, "Fresnel parameter eta of lobe 2 (Cook-Torrance dielectric)",
                 1.0, kUnbounded});
    return t;
  }
  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    T dp2, cos_dp;
    low_smooth_detail::projected(wi, wo, dp2, cos_dp);
    // seed 003 Eq. 34.
    return p[0] * T(kInvPi) + low_smooth_detail::abc(p[1], p[2], p[3], dp2) +
           DielectricFresnel<T>(p + 7).eval(cos_dp) * low_smooth_detail::abc(p[4], p[5], p[6], dp2);
  }
  static std::array<double, 3> probabilities(const double* p, const Vec3d& wo) {
    const double s1 = low_smooth_detail::abc_albedo_estimate(p[1], p[2], p[3]);
    const double s2 = DielectricFresnel<double>(p + 7).eval(wo.z()) * low_smooth_detail::abc_albedo_estimate(p[4], p[5], p[6]);
    return lobes::selection_probabilities<3>({p[0], s1, s2});
  }
  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double u_lobe) {
    switch (lobes::pick(probabilities(p, wo), u_lobe)) {
      case 0: return square_to_cosine_hemisphere(u);
      case 1: return low_smooth_detail::DiskSampler(p[2], wo).sample(u);
      default: return low_smooth_detail::DiskSampler(p[5], wo).sample(u);
    }
  }
  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    if (!(wi.z() > 0 && wo.z() > 0)) return 0.0;
    const auto prob = probabilities(p, wo);
    return prob[0] * cosine_hemisphere_pdf(wi) + prob[1] * low_smooth_detail::DiskSampler(p[2], wo).pdf(wi) +
           prob[2] * low_smooth_detail::DiskSampler(p[5], wo).pdf(wi);
  }
};

}  // namespace brdfkit
