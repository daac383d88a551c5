// The `he` model against an independent implementation: Greg Ward's Radiance function file
// He.cal ("He-Torrance Reflectance Model (Siggraph 1991)"), repository NREL/Radiance, path
// lib/He.cal, commit 47679cadb8caf78a09d02816f7441d311c19b445 (its spectral twin lib/He3.cal,
// commit 93757cd47db63b1a70dbd9139b372fbbd5f9f8e5, has the same formulas per channel). It was
// written from the paper in Radiance's expression language, shares no code with brdfkit, and
// differs from it in every numerical choice: its own complex Fresnel (He's form with u², v²),
// Newton on z0 in µm from a fixed start, the series summed forwards from m = 1 with an absolute
// stop, exp(x) flushed to 0 below x = −400. The reference below transcribes it line by line
// (Radiance names kept), with the wavelength as an argument (He.cal fixes 0.5 µm, He3.cal uses
// .67/.55/.43 µm per channel; brdfkit's channel wavelengths are fed to both sides).
//
// Radiance's conventions: D = ray direction (into the surface) = −wo, N = +z, RdotP = cos θr,
// (kix, kiy, kiz) = direction towards the light = wi. Its calcomp built-ins: if(a, b, c) is b when
// a > 0; or(a, b) = if(a, a, b); and(a, b) = if(a, b, a); Sqrt(x) = 0 for x < 0; Acos clamps;
// FTINY = 1e-7 (rayinit.cal). Grids stay clear of He.cal's own cut-offs at θ < 0.01 rad (S = 1)
// and θ > π/2 − 10⁻⁴ (S = 0).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "brdfkit/models/he_torrance.h"

namespace brdfkit {
namespace {

// He.cal's tunable constants. `published()` are the file's; `converged()` sums the series until
// the terms are exhausted and runs Newton to round-off, so that only the formulas are compared.
struct HeCalConstants {
  double z0err;    // accepted error in value of z0 (µm)
  double Dsumlim;  // last term of D summation
  int Dsummax;     // maximum terms in D summation
  static HeCalConstants published() { return {1e-4, 1e-6, 200}; }
  static HeCalConstants converged() { return {1e-13, 1e-300, 100000}; }
};

// Transcription of He.cal (see the header comment). Parameters as in its primitive: sigma0,
// tau (µm), n_real, n_imag; lambda (µm) replaces its constant.
class HeCal {
 public:
  HeCal(double sigma0, double tau, double n_real, double n_imag, double lambda, HeCalConstants k)
      : sigma0_(sigma0), tau_(tau), n_real_(n_real), n_imag_(n_imag), n_k_(n_imag / n_real), lambda_(lambda), c_(k) {}

  // ρ_dd = dd(kix, kiy, kiz) for the ray direction D = −wo.
  double dd(const Vec3d& wi, const Vec3d& wo) const {
    const Vec3d D = -wo;
    const double RdotP = wo.z();
    const double theta_r = std::acos(RdotP);
    const double shadowf_r = shadowf(theta_r);
    const double K_r = K(theta_r);
    const Vec3d kmd = wi - D;  // ki − D
    const double cti = wi.z();
    const double dd2 = shadowf_r * shadowf(Acos(cti)) / cti / RdotP;
    const double G = sq(kmd.squaredNorm() / kmd.z());
    const double fresnel2dd = fresnel2(kmd.norm() / 2);
    const double g = gfun(cti, RdotP, K_r);
    const double e = sq(2 * kPi / lambda_) / 4 * sq(tau_) * (kmd.squaredNorm() - sq(kmd.z()));
    const double Dterm = sq(kPi) / 4 / sq(lambda_) * sq(tau_) * Dsum(e, g);
    return dd2 * G * fresnel2dd / kPi * Dterm;
  }

  // Coefficient of the mirror reflection, s = fresnel2(RdotP) Exp(−g(RdotP)) shadowf_r².
  double s(double RdotP) const {
    const double theta_r = std::acos(RdotP);
    return fresnel2(RdotP) * Exp(-gfun(RdotP, RdotP, K(theta_r))) * sq(shadowf(theta_r));
  }

  // Set when z0root ran out of its 100 iterations (He.cal then uses z0 = 0).
  mutable bool z0_failed = false;

 private:
  static double sq(double x) { return x * x; }
  static double Exp(double x) { return -x - 400 > 0 ? 0.0 : std::exp(x); }  // "too timid" rayinit Exp
  static double Sqrt(double x) { return x < 0 ? 0.0 : std::sqrt(x); }
  static double Acos(double x) { return std::acos(std::clamp(x, -1.0, 1.0)); }
  static constexpr double FTINY = 1e-7;

  double cotexp(double t) const { return tau_ / sigma0_ / 2 / std::tan(t); }
  static double shadowf2(double et, double erfcet) {
    return (1 - .5 * erfcet) / ((Exp(-sq(et)) / std::sqrt(kPi) / et - erfcet) / 2 + 1);
  }
  double shadowf(double t) const {
    const double shadowf0 = std::fabs(t) - (kPi / 2 - .0001);
    const double a = FTINY - sigma0_, b = .01 - std::fabs(t);
    const double shadowf1 = a > 0 ? a : b;  // or()
    if (shadowf0 > 0) return 0;
    if (shadowf1 > 0) return 1;
    return shadowf2(cotexp(t), std::erfc(cotexp(t)));
  }
  double K(double t) const { return std::fabs(t) - FTINY > 0 ? std::tan(t) * std::erfc(cotexp(t)) : 0.0; }
  double fresnel2(double ct) const {
    const double fuvA = sq(n_real_) * (1 - sq(n_k_)) - (1 - sq(ct));
    const double fuvB = std::sqrt(sq(fuvA) + 4 * sq(sq(n_real_) * n_k_));
    const double fu2 = (fuvA + fuvB) / 2;
    const double fv2 = (-fuvA + fuvB) / 2;
    const double fperp2 = (sq(ct - std::sqrt(fu2)) + fv2) / (sq(ct + std::sqrt(fu2)) + fv2);
    const double fpara2 = (sq(sq(n_real_) * (1 - sq(n_k_)) * ct - std::sqrt(fu2)) +
                           sq(2 * sq(n_real_) * n_k_ * ct - Sqrt(fv2))) /
                          (sq(sq(n_real_) * (1 - sq(n_k_)) * ct + std::sqrt(fu2)) +
                           sq(2 * sq(n_real_) * n_k_ * ct + Sqrt(fv2)));
    return (fperp2 + fpara2) / 2;
  }
  // z0: Newton on sqrt(π/2) z = σ0/4 (Ki + Kr) exp(−z²/(2σ0²)), as z0root (recursion unrolled).
  double z0d(double Ki, double K_r, double z) const {
    return -(Ki + K_r) / (4 * sigma0_) * z * Exp(-sq(z / sigma0_) / 2) - std::sqrt(kPi / 2);
  }
  double z0lim(double x) const { return x > 0 ? std::max(x, c_.z0err) : std::min(x, -c_.z0err); }
  double z0off(double Ki, double K_r, double z) const {
    return (sigma0_ / 4 * (Ki + K_r) * Exp(-sq(z / sigma0_) / 2) - std::sqrt(kPi / 2) * z) / z0lim(z0d(Ki, K_r, z));
  }
  double z0(double ti, double K_r) const {
    const double Ki = K(ti);
    double x0 = .1, x1 = -z0off(Ki, K_r, .1);  // He.cal's first step, as written
    for (int i = 100; i > 0; --i) {
      if (c_.z0err - std::fabs(x1 - x0) > 0) return x1;
      x0 = x1;
      x1 = x1 - z0off(Ki, K_r, x1);
    }
    z0_failed = true;  // z0root's "i = 0" branch: gives up, z0 = 0, σ = σ0
    return 0;
  }
  double sigma(double ti, double K_r) const {
    return FTINY - sigma0_ > 0 ? sigma0_ : sigma0_ / std::sqrt(1 + sq(z0(ti, K_r) / sigma0_));
  }
  double gfun(double cti, double RdotP, double K_r) const {
    return sq(2 * kPi / lambda_ * sigma(Acos(cti), K_r) * (cti + RdotP));
  }
  // Dsum2 unrolled: stop (keeping the current term) once m > Dsummax, or once the terms
  // decrease and the current one is below Dsumlim.
  double Dsum(double e, double g) const {
    int m = 1;
    double lt = 0, c = g, t = g * Exp(-g - e), sum = 0;
    for (;;) {
      const double a = m - c_.Dsummax;
      const double b = lt - t > 0 ? c_.Dsumlim - t : lt - t;  // and()
      sum += t;
      if ((a > 0 ? a : b) > 0) break;  // or()
      lt = t;
      c = c * g / (m + 1);
      t = c * Exp(-g - e / (m + 1)) / (m + 1);
      ++m;
    }
    return sum;
  }

  double sigma0_, tau_, n_real_, n_imag_, n_k_, lambda_;
  HeCalConstants c_;
};

struct Surface {
  const char* name;
  double sigma0, tau, eta, k;
};

// Dielectric and conductor surfaces from nearly smooth (g ≪ 1: the lobe is a sliver around the
// mirror direction) to rough (g ≈ 60 at normal incidence). Aluminium's 0.96 + 6.69i as in the
// other He tests; the defaults of the model (0.18 µm, 3 µm) are those of BBM's He.
const std::vector<Surface>& surfaces() {
  static const std::vector<Surface> s{
      {"default dielectric", 0.18, 3.0, 1.5, 0.0},   {"polished aluminium", 0.05, 5.0, 0.96, 6.69},
      {"nearly smooth", 0.02, 5.0, 1.3, 2.0},        {"rough aluminium", 0.4, 2.0, 0.96, 6.69},
      {"steep dielectric", 0.3, 0.8, 1.8, 0.0},       {"glossy metal", 0.1, 1.5, 2.5, 3.5},
  };
  return s;
}

// Direction pairs: a coarse grid over the hemisphere plus a fine band around the mirror
// direction, where narrow lobes live.
std::vector<std::pair<Vec3d, Vec3d>> direction_pairs() {
  std::vector<std::pair<Vec3d, Vec3d>> pairs;
  const double deg = kPi / 180;
  for (double ti : {2.0, 20.0, 40.0, 60.0, 75.0, 85.0, 89.0}) {
    const Vec3d wi = spherical_direction(ti * deg, kPi);
    for (double to : {2.0, 15.0, 35.0, 55.0, 70.0, 84.0, 88.5}) {
      for (double phi : {0.0, 30.0, 90.0, 150.0, 180.0}) pairs.emplace_back(wi, spherical_direction(to * deg, phi * deg));
    }
    for (double dt : {-3.0, -1.0, -0.2, 0.0, 0.2, 1.0, 3.0}) {
      const double to = ti + dt;
      if (to < 1.0 || to > 89.5) continue;
      for (double phi : {0.0, 0.5, 2.0}) pairs.emplace_back(wi, spherical_direction(to * deg, phi * deg));
    }
  }
  return pairs;
}

using P = std::array<double, 6>;  // kd, ks, sigma0, tau, eta, k

// brdfkit's directional-diffuse term equals He.cal's dd with the series summed out: the only
// differences left are the truncation of brdfkit's series (≤ 1e-6 relative, he_series.h) and
// round-off (the two Fresnel forms, Newton in z0 vs z0/σ0).
TEST(HeReference, DirectionalDiffuseMatchesRadianceHeCal) {
  const auto pairs = direction_pairs();
  double worst = 0;
  int compared = 0, underflow = 0, z0_failures = 0;
  for (const Surface& s : surfaces()) {
    const P p{0.0, 1.0, s.sigma0, s.tau, s.eta, s.k};
    double worst_s = 0;
    for (int c = 0; c < 3; ++c) {
      const HeCal ref(s.sigma0, s.tau, s.eta, s.k, HeTorrance::wavelength_um(c), HeCalConstants::converged());
      for (const auto& [wi, wo] : pairs) {
        const double ours = HeTorrance::directional_diffuse<double>(p.data(), c, wi, wo);
        ref.z0_failed = false;
        const double theirs = ref.dd(wi, wo);
        if (ref.z0_failed) {
          ++z0_failures;
          continue;
        }
        if (theirs == 0) {  // Exp(x < −400) = 0 in He.cal: every term below e^{−400}
          ++underflow;
          EXPECT_LT(ours, 1e-150) << s.name;
          continue;
        }
        const double rel = std::fabs(ours / theirs - 1);
        worst_s = std::max(worst_s, rel);
        ++compared;
        EXPECT_LE(rel, 2e-6) << s.name << " channel " << c << " wi " << wi.transpose() << " wo " << wo.transpose()
                             << ": " << ours << " vs " << theirs;
      }
    }
    std::printf("[ he vs He.cal ] %-20s max |ours/He.cal - 1| = %.2e\n", s.name, worst_s);
    worst = std::max(worst, worst_s);
  }
  std::printf("[ he vs He.cal ] %d values compared (%d both ~0, %d skipped: He.cal's z0 did not converge), max "
              "relative difference %.2e\n", compared, underflow, z0_failures, worst);
  EXPECT_GT(compared, 3000);
}

}  // namespace
}  // namespace brdfkit

