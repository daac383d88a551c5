#pragma once
// Lafortune et al. 1997 generalized cosine lobes, as fitted in seed 002 (DESIGN.md §6):
// ρ = kd/π + Σⱼ ksⱼ (Nⱼ+2)/(2π max(|Cxyⱼ|, |Czⱼ|)^Nⱼ) · max(0, Cxyⱼ (ux vx + uy vy) + Czⱼ uz vz)^Nⱼ.
// The max(0, ·) clamp keeps non-integer N real where the generalized dot product is negative
// (Cxy < 0 is the usual, mirror-like case); Ngan's normalization (as transcribed by the BBM
// benchmark) divides by max(|Cxy|, |Cz|)^N so the raw form's flat direction (C·s, ks·s⁻ᴺ)
// disappears and ks is about the lobe's albedo. Reciprocal: symmetric in u = wi and v = wo.
//
// Sampling: lobe j is cosᴺα about its axis aⱼ = (Cxy vx, Cxy vy, Cz vz)/|·| (the value is
// ksⱼ (N+2)/(2π) (|aⱼ|/m)ᴺ cosᴺα), drawn with density (N+1)/(2π) cosᴺα; draws below the
// horizon are rejected. Lobes and the diffuse term are picked ∝ albedo estimates.
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "brdfkit/core/warp.h"
#include "brdfkit/models/lobe_mixture.h"
#include "brdfkit/core/param.h"

namespace brdfkit {

template <int L> struct LafortuneLobes {
  static_assert(L >= 1);
  static constexpr int kPerLobe = 4;  // ks, Cxy, Cz, N

  static std::string_view name() {
    if constexpr (L == 1) return "lafortune";
    else return "lafortune-2";
  }
  static std::string_view description() {
    if constexpr (L == 1) return "Lambert + one Lafortune 1997 generalized cosine lobe (Ngan's normalization)";
    else return "Lambert + two Lafortune 1997 generalized cosine lobes (Ngan's normalization)";
  }
  static constexpr bool kReciprocal = true;
  static ParamTable params() {
    ParamTable t{{"kd", 0.0, 1.0, 0.5, Scope::PerChannel, true, "diffuse albedo (Lambertian kd/pi)"}};
    for (int j = 0; j < L; ++j) {
      const std::string s = L == 1 ? "" : std::to_string(j + 1);
      const double n_def = j == 0 ? 20.0 : 4.0;  // distinct defaults: identical lobes are a degenerate start
      t.push_back({"ks" + s, 0.0, 1.0, j == 0 ? 0.1 : 0.05, Scope::PerChannel, true,
                   "lobe scale, ~ its albedo (Lafortune 1997, Ngan's normalization)"});
      t.push_back({"Cxy" + s, -1.0, 1.0, -1.0, Scope::Shared, false,
                   "tangential coefficient; -1 with Cz = 1 is the mirror lobe (Lafortune 1997)"});
      t.push_back({"Cz" + s, 0.0, 1.0, 1.0, Scope::Shared, false, "normal coefficient (Lafortune 1997)"});
      // The fitter searches N ≤ 10⁴; the lobe is defined for any N ≥ 0 (xᴺ of x ∈ [0, 1]).
      t.push_back({"N" + s, 0.0, 1e4, n_def, Scope::Shared, false, "lobe exponent (sharpness)", 0.0, kUnbounded});
    }
    return t;
  }

  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    using std::pow;
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    T sum = p[0] * T(kInvPi);
    for (int j = 0; j < L; ++j) {
      const T* q = p + 1 + kPerLobe * j;
      const T ax = q[1] < T(0) ? -q[1] : q[1];
      const T az = q[2] < T(0) ? -q[2] : q[2];
      const T m = ax > az ? ax : az;
      if (!(m > T(0))) continue;
      const T dot = q[1] * (wi.x() * wo.x() + wi.y() * wo.y()) + q[2] * wi.z() * wo.z();
      if (!(dot > T(0))) continue;  // the clamp of DESIGN.md §6
      sum += q[0] * (q[3] + T(2)) / T(2 * kPi) * pow(dot / m, q[3]);
    }
    return sum;
  }

  // Lobe axis (unnormalized) and its length relative to max(|Cxy|, |Cz|).
  struct Axis {
    Vec3d dir;     // unit, or zero when the lobe vanishes
    double scale;  // |a| / m ∈ [0, 1]
  };
  static Axis axis(const double* q, const Vec3d& wo) {
    const double m = std::max(std::abs(q[1]), std::abs(q[2]));
    const Vec3d a(q[1] * wo.x(), q[1] * wo.y(), q[2] * wo.z());
    const double len = a.norm();
    if (!(m > 0 && len > 0)) return {Vec3d::Zero(), 0.0};
    return {a / len, len / m};
  }
  static std::array<double, L + 1> probabilities(const double* p, const Vec3d& wo) {
    std::array<double, L + 1> w{};
    w[0] = p[0];
    for (int j = 0; j < L; ++j) {
      const double* q = p + 1 + kPerLobe * j;
      const Axis a = axis(q, wo);
      // Peak value scale times the lobe's cosine towards n (floored so a lobe near the horizon keeps some samples).
      w[size_t(j + 1)] = q[0] * std::pow(a.scale, q[3]) * std::max(a.dir.z(), 0.05);
      if (!(a.scale > 0)) w[size_t(j + 1)] = 0;
    }
    return lobes::selection_probabilities<L + 1>(w);
  }

  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double u_lobe) {
    const auto prob = probabilities(p, wo);
    const size_t k = lobes::pick(prob, u_lobe);
    if (k == 0) return square_to_cosine_hemisphere(u);
    const double* q = p + 1 + kPerLobe * int(k - 1);
    const Axis a = axis(q, wo);
    if (!(a.scale > 0)) return std::nullopt;
    const Vec3d wi = frame_around(a.dir) * lobes::sample_cosine_power(q[3], u);
    if (!(wi.z() > 0)) return std::nullopt;
    return wi;
  }
  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    if (!(wi.z() > 0 && wo.z() > 0)) return 0.0;
    const auto prob = probabilities(p, wo);
    double sum = prob[0] * cosine_hemisphere_pdf(wi);
    for (int j = 0; j < L; ++j) {
      const double* q = p + 1 + kPerLobe * j;
      const Axis a = axis(q, wo);
      if (a.scale > 0) sum += prob[size_t(j + 1)] * lobes::cosine_power_pdf(q[3], a.dir.dot(wi));
    }
    return sum;
  }
};

using Lafortune = LafortuneLobes<1>;
using Lafortune2 = LafortuneLobes<2>;

}  // namespace brdfkit
