#pragma once
// He, Torrance, Sillion & Greenberg 1991, "A Comprehensive Physical Model for Light Reflection"
// (SIGGRAPH '91), the unpolarized isotropic model of its appendix (Eq. 69–86), as compared in
// seed 002 (DESIGN.md §6):
//   ρ = kd/π  +  ks · F G S D / (π cosθi cosθr)  [+ the specular spike, see below]
// with, for channel c at wavelength λ = kChannelWavelengthUm[c] (µm) and k = 2π/λ:
//   F  Fresnel reflectance of the complex index η + i k at the bisector angle, cos = |wi + wo|/2
//      (fresnel/conductor.h; k = 0 is a dielectric);
//   G  = (v·v / v_z)², v = wi + wo (Eq. 76: the polarization brackets of the unpolarized case
//      equal |k̂i × k̂r|² each and cancel the 1/|k̂i × k̂r|⁴);
//   S  = S(θi) S(θr), Smith shadowing with He's errata (he_shadowing.h, Eq. 23–25);
//   D  = π²τ²/(4λ²) Σ_{m≥1} e^{−g} gᵐ/(m!·m) exp(−τ² v_xy²/(4m))   (Eq. 78, he_series.h),
//      g = (k σ (cosθi + cosθr))² (Eq. 79) with σ the effective roughness (Eq. 80–83), and
//      v_xy = k |(wi + wo)_xy| — the wave vector k(k̂r − k̂i), as in Westin's reference code and
//      Radiance's He.cal. (Reading v as a unit-less difference of unit vectors, as BBM's "he"
//      variant does, is not dimensionally consistent: τ² v_xy² must be unit-less.) With this
//      reading the rough limit g ≫ 1 is exactly Cook-Torrance with a Beckmann distribution of
//      α = 2σ/τ and Fresnel F, and the smooth limit conserves energy with the spike; both are
//      tested (tests/catalogue_he), and the whole directional-diffuse term and spike agree with
//      an in-test transcription of Radiance's He.cal (NREL/Radiance lib/He.cal, its series summed
//      out) to 6.8e-7 relative (tests/catalogue_he/test_he_reference.cpp).
// kd is He's uniform-diffuse term a(λ) as an albedo (Lambertian, DESIGN.md §6). ks scales the
// directional-diffuse term: 1 is He's physical model; seed 002 §3.1 fits a free colour scale.
//
// The specular spike (Eq. 74), ρ_sp = ks |F(θi)|² e^{−g} S(θi)² · δ(wr − mirror(wi)) / cosθi, is a
// Dirac delta: it has no value at any pair of directions a measurement or a MERL cell holds, so
// `eval` (and with it fitting, metrics, tabulation) omits it, as the Holzschuch-Pacanowski and
// BBM implementations of He's model do (seed 002 does not print its formulas; they are in its
// supplemental). Its reflectance is `specular_reflectance` so albedo budgets can add it.
//
// Reciprocal: every factor is symmetric in (wi, wo), and computed from symmetric sums.
// Sampling: kd cosine-weighted, or a Beckmann half-vector lobe (`lobe_alpha`) reflected about
// wo, mixed by kd and an estimate of the directional-diffuse albedo.
#include <cmath>
#include <cstddef>
#include <optional>
#include <string_view>
#include <type_traits>

#include "brdfkit/core/vec.h"
#include "brdfkit/fresnel/conductor.h"
#include "brdfkit/models/he_effective_roughness.h"
#include "brdfkit/models/he_series.h"
#include "brdfkit/models/he_series_table.h"
#include "brdfkit/models/he_shadowing.h"
#include "brdfkit/core/param.h"

namespace brdfkit {

struct HeTorrance {
  // Indices into the parameter table.
  enum : int { kKd = 0, kKs = 1, kSigma0 = 2, kTau = 3, kEta = 4, kK = 5 };
  // Relative truncation of the Eq. 78 series (he_series.h bounds the omitted part by it).
  static constexpr double kSeriesTolerance = 1e-6;

  static std::string_view name() { return "he"; }
  static std::string_view description() {
    return "He-Torrance-Sillion-Greenberg 1991: uniform diffuse + directional diffuse (Kirchhoff series), "
           "complex index, per-channel wavelength";
  }
  static constexpr bool kReciprocal = true;
  static ParamTable params() {
    return {{"kd", 0.0, 1.0, 0.2, Scope::PerChannel, true, "uniform-diffuse albedo a(lambda) as kd/pi (He 1991 Eq. 69)"},
            {"ks", 0.0, 2.0, 1.0, Scope::PerChannel, true,
             "scale of the directional-diffuse term; 1 = He's physical model (seed 002 fits it freely)"},
            // The fitter's box; the series and its tables are checked to 10 µm and 200 µm
            // (tests/models/test_param_domains.cpp), which Ngan's published fits need (σ0 8.74, τ 103).
            {"sigma0", 0.005, 2.0, 0.18, Scope::Shared, false, "RMS surface height sigma0 in um (He 1991 §2)", 0.005, 10.0},
            {"tau", 0.1, 50.0, 3.0, Scope::Shared, false, "surface autocorrelation length tau in um (He 1991 §2)", 0.1, 200.0},
            {"eta", 0.01, 100.0, 1.5, Scope::PerChannel, false, "real part of the complex index n (He 1991 Eq. 70)"},
            {"k", 0.0, 100.0, 0.0, Scope::PerChannel, false, "imaginary part of the complex index (0: dielectric)"}};
  }

  static double wavelength_um(int c) { return kChannelWavelengthUm[c < 0 || c > 2 ? 1 : c]; }

  // Eq. 78's series: doubles at the default tolerance from its table (he_series_table.h, within
  // that tolerance), Jets, statistics and tighter tolerances summed (he_series.h).
  template <class T> static T series(const T& g, const T& c, double tolerance, HeSeriesStats* stats) {
    if constexpr (std::is_same_v<T, double>)
      if (!stats && tolerance >= HeSeriesTable::kRelativeError) return HeSeriesTable::get()(g, c);
    return he_series(g, c, tolerance, stats);
  }

  // The directional-diffuse term alone, without ks (He 1991 Eq. 75).
  template <class T>
  static T directional_diffuse(const T* p, int c, const Vec3<T>& wi, const Vec3<T>& wo, HeSeriesStats* stats = nullptr,
                               double series_tolerance = kSeriesTolerance) {
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    const HeSlopeTerms<T> slope_i(wi.z(), p[kSigma0], p[kTau]), slope_o(wo.z(), p[kSigma0], p[kTau]);
    return directional_diffuse_with(p, c, wi, wo, slope_i, slope_o, stats, series_tolerance);
  }

  // What the directional-diffuse term of one pair takes from the shape alone: the same in every
  // channel, so a batch over R, G and B computes it once per pair (eval_batch_rgb).
  template <class T> struct PairTerms {
    Vec3<T> v;  // k̂r − k̂i = wi + wo (k̂i = −wi): symmetric in (wi, wo)
    T vxy2, vv, geometry, shadow, sigma;
  };
  template <class T>
  static PairTerms<T> pair_terms(const T* p, const Vec3<T>& wi, const Vec3<T>& wo, const HeSlopeTerms<T>& slope_i,
                                 const HeSlopeTerms<T>& slope_o) {
    return pair_terms(wi, wo, slope_i.shadowing * slope_o.shadowing,                             // Eq. 23
                      he_effective_roughness_of(slope_i.k_factor + slope_o.k_factor, p[kSigma0]));  // Eq. 80
  }
  // The same with S(θi)S(θr) and σ given (they depend on the two cosines alone).
  template <class T>
  static PairTerms<T> pair_terms(const Vec3<T>& wi, const Vec3<T>& wo, const T& shadow, const T& sigma) {
    PairTerms<T> t;
    t.v = wi + wo;
    t.vxy2 = t.v.x() * t.v.x() + t.v.y() * t.v.y();
    t.vv = t.vxy2 + t.v.z() * t.v.z();
    t.geometry = (t.vv / t.v.z()) * (t.vv / t.v.z());  // Eq. 76 (unpolarized)
    t.shadow = shadow;
    t.sigma = sigma;
    return t;
  }

  // The directional-diffuse term of channel c from the pair's shape terms.
  template <class T>
  static T directional_diffuse_of(const T* p, int c, const Vec3<T>& wi, const Vec3<T>& wo, const PairTerms<T>& t,
                                  HeSeriesStats* stats = nullptr, double series_tolerance = kSeriesTolerance) {
    return directional_diffuse_by(p, c, wi, wo, t,
                                  [&](const T& g, const T& c_exp) { return series(g, c_exp, series_tolerance, stats); });
  }
  // The same with Eq. 78's series given as series_of(g, c).
  template <class T, class Series>
  static T directional_diffuse_by(const T* p, int c, const Vec3<T>& wi, const Vec3<T>& wo, const PairTerms<T>& t,
                                  Series&& series_of) {
    const Unsummed<T> u = unsummed(p, c, wi, wo, t);
    return u.of(series_of(u.g, u.c));
  }

  // Eq. 75 around Eq. 78's series S(g, c): ρ_dd = front · (scale · S) / den, so that a batch can
  // look up the series of many pairs at once (HeSeriesTable::block).
  template <class T> struct Unsummed {
    T g, c;            // the series' arguments
    T front, scale, den;
    T of(const T& series) const { return front * (scale * series) / den; }
  };
  template <class T>
  static Unsummed<T> unsummed(const T* p, int c, const Vec3<T>& wi, const Vec3<T>& wo, const PairTerms<T>& t) {
    return unsummed_of(p, c, t.vv, t.v.z(), t.vxy2, t.sigma, t.geometry, t.shadow, T(kPi) * wi.z() * wo.z());
  }
  // Eq. 78's factor of the series, π²τ²/(4λ²): the same at every pair.
  template <class T> static T series_scale(const T* p, int c) {
    const double lambda = wavelength_um(c);
    return T(kPi * kPi / (4 * lambda * lambda)) * p[kTau] * p[kTau];
  }
  // The same from the pair terms' numbers and den = π cosθi cosθr: plain arithmetic, which
  // he_channel_block (he_batch_block.h) runs on a block of pairs with vector instructions.
  template <class T>
  static Unsummed<T> unsummed_of(const T* p, int c, const T& vv, const T& vz, const T& vxy2, const T& sigma,
                                 const T& geometry, const T& shadow, const T& den) {
    return unsummed_with(p, c, front_of(p, vv, geometry, shadow), vz, vxy2, sigma, den);
  }
  // Eq. 75's F G S: the Fresnel factor at the bisector angle, cos = |v|/2. The channels share it
  // where they share η and k (he_batch_block.h).
  template <class T> static T front_of(const T* p, const T& vv, const T& geometry, const T& shadow) {
    using std::sqrt;
    const T fresnel = ConductorFresnel<T>(p + kEta).eval(T(0.5) * sqrt(vv));
    return fresnel * geometry * shadow;  // Eq. 75
  }
  // unsummed_of with its front_of given.
  template <class T>
  static Unsummed<T> unsummed_with(const T* p, int c, const T& front, const T& vz, const T& vxy2, const T& sigma,
                                   const T& den) {
    const T& tau = p[kTau];
    const double lambda = wavelength_um(c);
    const double k = 2 * kPi / lambda;
    const T kg = T(k) * sigma * vz;
    Unsummed<T> u;
    u.g = kg * kg;                                              // Eq. 79
    u.c = T(0.25 * k * k) * tau * tau * vxy2;                   // τ² v_xy²/4, v_xy = k |v_xy|
    u.scale = series_scale(p, c);
    u.front = front;
    u.den = den;
    return u;
  }

  // c/g of unsummed_of, τ² v_xy² / (4 σ² v_z²) with v unit-less: the same in every channel, so
  // the channels of a pair share the table's rows (HeSeriesTable::rows).
  static double series_ratio(double tau, double vxy2, double sigma, double vz) {
    const double sigma_vz = sigma * vz;
    return 0.25 * tau * tau * vxy2 / (sigma_vz * sigma_vz);  // Eq. 78–79: c / g, k² cancelled
  }

  // The same with the slope terms of wi and wo given (both directions above the horizon).
  template <class T>
  static T directional_diffuse_with(const T* p, int c, const Vec3<T>& wi, const Vec3<T>& wo,
                                    const HeSlopeTerms<T>& slope_i, const HeSlopeTerms<T>& slope_o,
                                    HeSeriesStats* stats = nullptr, double series_tolerance = kSeriesTolerance) {
    return directional_diffuse_of(p, c, wi, wo, pair_terms(p, wi, wo, slope_i, slope_o), stats, series_tolerance);
  }

  template <class T> static T eval(const T* p, int c, const Vec3<T>& wi, const Vec3<T>& wo) {
    if (!(wi.z() > T(0) && wo.z() > T(0))) return T(0);
    return p[kKd] * T(kInvPi) + p[kKs] * directional_diffuse(p, c, wi, wo);
  }

  // eval for n pairs. What depends on the cosines alone is kept while they repeat (a metric's grid
  // holds one incidence per chunk and varies Δφ fastest, fit/metric/metric_grid.h, so the slope
  // terms and σ are computed once per (θi, θo) there, eight new pairs at a time on vector lanes,
  // he_batch_block.h), and the series of a block of pairs is looked up at once
  // (HeSeriesTable::block_at): eval's values within the table's block bounds (1e-12 relative,
  // 1e-11 where c/g > 1000).
  static void eval_batch(const double* p, int c, std::size_t n, const double* wi_x, const double* wi_y,
                         const double* wi_z, const double* wo_x, const double* wo_y, const double* wo_z,
                         double* out);

  // eval_batch for R, G and B (p[c]: channel c's parameters) with the pair's shape terms computed
  // once for the three: eval_batch's values to the bit. Where σ0 or τ differ between the
  // channels, three eval_batch.
  static void eval_batch_rgb(const double* const p[3], std::size_t n, const double* wi_x, const double* wi_y,
                             const double* wi_z, const double* wo_x, const double* wo_y, const double* wo_z,
                             double* const out[3]);

  // eval_batch at p from its values at_p0 at p0 where the two differ only in η and k: they enter
  // only through the Fresnel factor of Eq. 75, so ρ(p) = kd/π + (ρ(p0) − kd/π) F_p / F_p0. A pair
  // where F_p0 = 0, or where ρ(p0) − kd/π is too small beside kd/π to keep its digits, is evaluated
  // in full. False where any other parameter differs.
  static bool eval_batch_from(const double* p, const double* p0, const double* at_p0, int c, std::size_t n,
                              const double* wi_x, const double* wi_y, const double* wi_z, const double* wo_x,
                              const double* wo_y, const double* wo_z, double* out);

  // Weight ks |F(θi)|² e^{−g} S(θi)² of the specular spike at incidence cosθi (He 1991 Eq. 74,
  // with θr = θi): the directional reflectance the delta adds to ∫ ρ cosθr dωr.
  static double specular_reflectance(const double* p, int c, double cos_i);

  // Width of the Beckmann half-vector lobe the sampler draws from: the rough limit 2σ0/τ of the
  // series combined with the width λ/(2πτ) of its first term (the smooth limit at normal incidence).
  static double lobe_alpha(const double* p, int c);

  static std::optional<Vec3d> sample(const double* p, int c, const Vec3d& wo, const Vec2d& u, double u_lobe);
  static double pdf(const double* p, int c, const Vec3d& wo, const Vec3d& wi);
};

}  // namespace brdfkit
