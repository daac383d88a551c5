#pragma once
// Löw et al.'s ABC facet distribution (seed 003 Eq. 15 with S of Eq. 11, DESIGN.md §3):
//   S(θ) = A / (1 + B (1 − cosθ))^C, unnormalized (A is the lobe's scale in seed 003).
// normalization() gives ∫ S cosθ dω in closed form: with w = 1 + B(1−cosθ), L = ln(1+B) and
// E(a, L) = (e^{aL} − 1)/a = ∫₁^{e^L} w^{a−1} dw,
//   ∫ S cosθ dω = 2π A [(1+B) E(1−C, L) − E(2−C, L)] / B².
// normalized() rescales A so that the interface contract ∫ D cosθ dω = 1 holds (used by Λ).
// sample() draws density D cosθ (the interface) by inverting that CDF with toms748;
// sample_paper()/pdf_paper() are seed 003 Eq. 23–26: density ∝ S over solid angle (no cosθ).
// Interface: ndf/distribution.h.
#include <cmath>
#include <string_view>
#include <type_traits>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/param.h"
#include "brdfkit/ndf/distribution.h"
#include "brdfkit/ndf/slope_space.h"

namespace brdfkit {

// E(a, L) = expm1(a L)/a, continuous through a = 0 (series for |a L| < 1e-6, error < 1e-19 L).
template <class T> T abc_expm1_ratio(const T& a, const T& L) {
  using std::expm1;
  const T aL = a * L;
  if (aL < T(1e-6) && aL > T(-1e-6)) return L * (T(1) + aL / T(2) + aL * aL / T(6));
  return expm1(aL) / a;
}

template <class T> struct AbcFacet {
  static constexpr std::string_view kName = "abc-facet", kTitle = "ABC facet";
  T A, B, C;

  static ParamTable params() {
    return {{"A", 0.0, 1e8, 1.0, Scope::Shared, true, "ABC facet scale (seed 003 Eq. 11, 15)"},
            {"B", 1e-3, 1e8, 100.0, Scope::Shared, false, "ABC facet sharpness, B = b^2 (seed 003 Eq. 11)"},
            {"C", 1e-3, 10.0, 1.0, Scope::Shared, false, "ABC facet tail exponent (seed 003 Eq. 11)"}};
  }
  explicit AbcFacet(const T* p) : A(p[0]), B(p[1]), C(p[2]) {}

  T unit(const T& cos_theta) const {
    using std::log1p;
    using std::exp;
    if (!(cos_theta > T(0))) return T(0);
    // (1 + B(1−c))^{−C} through log1p: B(1−c) spans 1e-12 … 1e8.
    return exp(-C * log1p(B * (T(1) - cos_theta)));
  }
  T D(const T& cos_theta) const { return A * unit(cos_theta); }
  T P22(const T& x) const { return p22_from_d(*this, x); }
  // ∫ D cosθ dω (see the header comment).
  T normalization() const { return T(2 * kPi) * A * cos_weighted_mass(); }
  AbcFacet normalized() const {
    AbcFacet r = *this;
    r.A = T(1) / (T(2 * kPi) * cos_weighted_mass());
    return r;
  }
  // The distribution whose Smith Λ this one has (shadowing/smith.h): Λ needs ∫ D cosθ dω = 1.
  AbcFacet smith_form() const { return normalized(); }

  // ∫_c^1 (1 + B(1−c'))^{−C} c' dc' as a function of L = ln(1 + B(1−c)) ∈ [0, ln(1+B)].
  // Relative rounding error ~ 1e-16/B (the two terms cancel for small B; B ≥ 1e-3 here).
  T cos_weighted_mass_L(const T& L) const {
    return ((T(1) + B) * abc_expm1_ratio(T(1) - C, L) - abc_expm1_ratio(T(2) - C, L)) / (B * B);
  }
  // The same over the whole hemisphere (c = 0).
  T cos_weighted_mass() const {
    using std::log1p;
    return cos_weighted_mass_L(log1p(B));
  }

  Vec3d sample(const Vec2d& u) const
    requires std::is_same_v<T, double>;
  double pdf(const Vec3d& m) const
    requires std::is_same_v<T, double>
  {
    return D(m.z()) * std::max(0.0, m.z()) / normalization();
  }

  // Seed 003 Eq. 25–26 with Eq. 24's M_h: P(w ≤ W) = (W^{1−C} − 1)/((1+B)^{1−C} − 1), so
  // ln w = ln(1 + ξ ((1+B)^{1−C} − 1))/(1−C) (ξ ln(1+B) at C = 1). Written with log1p/expm1
  // it needs no C ≈ 1 special case (seed 003 §4 falls back to C = 1 there).
  Vec3d sample_paper(const Vec2d& u) const
    requires std::is_same_v<T, double>
  {
    const double L = std::log1p(B), a = 1.0 - C;
    const double lw = std::abs(a * L) < 1e-9 ? u.x() * L : std::log1p(u.x() * std::expm1(a * L)) / a;
    const double c = std::clamp(1.0 - std::expm1(lw) / B, 0.0, 1.0);
    return isotropic_normal(c, u.y());
  }
  // Seed 003 Eq. 23–24: S / ∫ S dω, ∫ S dω = 2π A E(1−C, ln(1+B)) / B.
  double pdf_paper(const Vec3d& m) const
    requires std::is_same_v<T, double>
  {
    if (!(m.z() > 0.0)) return 0.0;
    return unit(m.z()) * B / (2 * kPi * abc_expm1_ratio(1.0 - C, std::log1p(B)));
  }
};

// Root of mass(L) = u · mass(ln(1+B)) in L by toms748 (the CDF of D cosθ in w = e^L).
Vec3d abc_facet_sample(const AbcFacet<double>& d, const Vec2d& u);

template <class T>
Vec3d AbcFacet<T>::sample(const Vec2d& u) const
  requires std::is_same_v<T, double>
{
  return abc_facet_sample(*this, u);
}

// Smith Λ table over (log B, log C) of the normalized distribution (A drops out of Λ).
template <> struct SmithShape<AbcFacet> {
  static constexpr int kDims = 2;
  static std::vector<SmithAxis> axes() { return {{1e-3, 1e8, 240, true}, {1e-3, 10.0, 160, true}}; }
  template <class T> static std::array<T, 2> values(const AbcFacet<T>& d) { return {d.B, d.C}; }
  static AbcFacet<double> make(const double* c) {
    const double p[3] = {1.0, c[0], c[1]};
    return AbcFacet<double>(p).normalized();
  }
};

}  // namespace brdfkit
