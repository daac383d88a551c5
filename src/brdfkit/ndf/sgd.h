#pragma once
// Shifted gamma distribution (SGD), seed 000 §4.2 with its 1/π (DESIGN.md §3):
//   P22(x) = α^{p−1}/Γ(1−p, α) · exp(−(α²+x)/α) / (α²+x)^p / π,  x = tan²θ.
// With t = α + x/α this is K e^{−t} t^{−p} / π, K = 1/(α Γ(1−p, α)): the K that the published
// Bagher fits list (data/published-fits/bagher2012-sgd.json `conventions`).
// Γ(1−p, α) for 1−p ≤ 0 via upper_gamma.h. Jets: K carries exact derivatives (∂Γ/∂x closed
// form, ∂Γ/∂s by quadrature). Interface: ndf/distribution.h.
#include <cmath>
#include <string_view>
#include <type_traits>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/param.h"
#include "brdfkit/ndf/distribution.h"
#include "brdfkit/ndf/d_block.h"
#include "brdfkit/ndf/ggx.h"
#include "brdfkit/core/upper_gamma.h"

namespace brdfkit {

template <class T> struct Sgd {
  static constexpr std::string_view kName = "sgd", kTitle = "SGD";
  T alpha;
  T p;
  T K;  // 1/(α Γ(1−p, α))

  static ParamTable params() {
    return {{"alpha", 1e-6, 2.0, 0.05, Scope::Shared, false, "SGD alpha: slope and slope^2 scale (seed 000 Sec. 4.2)"},
            {"p", 0.0, 1.95, 0.5, Scope::Shared, false, "SGD shift exponent; 1-p > -1 needed by Gamma(1-p, alpha) (seed 000 Sec. 4.2)"}};
  }
  explicit Sgd(const T* params) : alpha(params[0]), p(params[1]), K(T(1) / (alpha * upper_gamma<T>(T(1) - p, alpha))) {}

  // K e^{−t} t^{−p}/π = K e^{−t − p ln t}/π, t = α + x/α: the published form, free of α^{p−1}
  // over/underflow, with one exp and one log (a pow would cost both again).
  T P22(const T& x) const {
    using std::exp;
    using std::log;
    const T t = alpha + x / alpha;
    return K * exp(-t - p * log(t)) / T(kPi);
  }
  // P22 at the kP22Block slopes x[0 … kP22Block), for the Smith integral's nodes.
  void P22_block(const double* x, double* out) const
    requires std::is_same_v<T, double>
  {
    sgd_p22_block(K, alpha, p, x, out);
  }
  T D(const T& cos_theta) const {
    if (!(cos_theta > T(0))) return T(0);
    const T c2 = cos_theta * cos_theta;
    return P22((T(1) - c2) / c2) / (c2 * c2);
  }
  // D at the kDBlock cosines c[0 … kDBlock) (ndf/d_block.h), for the batch loops.
  void D_block(const double* c, double* out) const
    requires std::is_same_v<T, double>
  {
    sgd_d_block(K, alpha, p, c, out);
  }
  // D/D(0) = e^{−(t−α)} (α/t)^p with t = α + tan²θ/α.
  T unit(const T& cos_theta) const {
    using std::exp;
    using std::pow;
    if (!(cos_theta > T(0))) return T(0);
    const T c2 = cos_theta * cos_theta;
    const T x = (T(1) - c2) / c2;
    const T t = alpha + x / alpha;
    return exp(-x / alpha) * pow(alpha / t, p) / (c2 * c2);
  }

  // Exact inversion of Fθ = 1 − Γ(1−p, α + tan²θ/α)/Γ(1−p, α) (seed 000 §4.5): Boost's
  // gamma_q_inv for 1−p > 0, toms748 root finding on Γ for 1−p ≤ 0 (no regularized form).
  Vec3d sample(const Vec2d& u) const
    requires std::is_same_v<T, double>;
  double pdf(const Vec3d& m) const
    requires std::is_same_v<T, double>
  {
    return D(m.z()) * std::max(0.0, m.z());
  }

  // Seed 000 §4.5's proxy: m from GGX with width α (tanθ = α sqrt(u/(1−u))), weight = the
  // ratio of SGD's density to GGX's, D_sgd(m)/D_ggx(m), so that E[w f(m)] = ∫ f D_sgd cos dω.
  // (The paper's printed BRDF weight misses |i·m|/cosθi, DESIGN.md §6; that factor belongs
  // to the BRDF's half-vector Jacobian, not to this density ratio.)
  Vec3d sample_ggx_proxy(const Vec2d& u, double* weight) const
    requires std::is_same_v<T, double>;
};

// Inverse of Fθ: t ∈ [α, ∞) with Γ(s, t) = (1−u) Γ(s, α), s = 1−p; tan²θ = α (t − α).
Vec3d sgd_sample(double alpha, double p, const Vec2d& u);

template <class T>
Vec3d Sgd<T>::sample(const Vec2d& u) const
  requires std::is_same_v<T, double>
{
  return sgd_sample(alpha, p, u);
}

template <class T>
Vec3d Sgd<T>::sample_ggx_proxy(const Vec2d& u, double* weight) const
  requires std::is_same_v<T, double>
{
  const Ggx<double> ggx(&alpha);
  const Vec3d m = ggx.sample(u);
  const double d_ggx = ggx.D(m.z());
  *weight = d_ggx > 0.0 ? D(m.z()) / d_ggx : 0.0;
  return m;
}

// Smith Λ table over (log α, p); p below 0 only as an interpolation margin (the edge cells of
// Catmull-Rom are the weakest).
template <> struct SmithShape<Sgd> {
  static constexpr int kDims = 2;
  // p below 0 only as an interpolation margin (the edge cells of Catmull-Rom are the weakest).
  static std::vector<SmithAxis> axes() { return {{1e-6, 2.0, 49, true}, {-0.15, 1.95, 29, false}}; }
  template <class T> static std::array<T, 2> values(const Sgd<T>& d) { return {d.alpha, d.p}; }
};

}  // namespace brdfkit
