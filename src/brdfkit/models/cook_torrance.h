#pragma once
// Cook-Torrance microfacet reflection over a Lambertian base (seed 004 Eq. 1, DESIGN.md §6):
//   ρ(wi, wo) = kd/π + ks F(θd) D(θh) G(wi, wo) / (4 cosθi cosθo),
// with any distribution of ndf/ (the interface of ndf/beckmann.h), any Fresnel term of fresnel/
// (`explicit X(const T* p)`, `params()`, `eval(cos θd)`) and a selectable masking term.
// Seed 000 Eq. 1 writes the same lobe as ρs/π · F D G/(cosθi cosθo): ks = 4 ρs/π (see
// ks_from_bagher_rho_s below); its ρd equals kd.
//
// Parameters, in this order: kd (per channel, linear), ks (per channel, linear), then
// Ndf::params(), then Fresnel::params(). One evaluation template (`eval_at`) serves doubles,
// the structure-of-arrays batch loop (`eval_batch`) and ceres::Jet.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <optional>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/warp.h"
#include "brdfkit/measured/sample_set.h"
#include "brdfkit/core/param.h"
#include "brdfkit/ndf/beckmann.h"
#include "brdfkit/ndf/d_block.h"
#include "brdfkit/shadowing/smith.h"
#include "brdfkit/shadowing/smith_g1_row.h"

namespace brdfkit {

enum class Masking {
  SmithUncorrelated,  // G1(i) G1(o), the seeds' choice (seed 000 Eq. 6, seed 004 Eq. 4–7)
  SmithCorrelated,    // 1/(1 + Λ(i) + Λ(o)), height-correlated (DESIGN.md §4)
  VGroove,            // Cook & Torrance 1982 (DESIGN.md §4)
};

// Seed 000 Eq. 1 (ρs/π · FDG/(cosθi cosθo)) and seed 004 Eq. 1 (ks FDG/(4 cosθi cosθo)) are
// equal when ks/4 = ρs/π.
inline double ks_from_bagher_rho_s(double rho_s) { return 4.0 * rho_s * kInvPi; }
inline double bagher_rho_s_from_ks(double ks) { return ks * kPi / 4.0; }

// Whether the batch loops read Smith G1 from a row (shadowing/smith_g1_row.h): every distribution
// with a Λ table, except those whose closed-form Λ costs less than the row (kCheapLambda: GGX's is
// one square root; Beckmann's erfc and exp cost more).
template <template <class> class Ndf>
constexpr bool kG1FromRow = SmithShape<Ndf>::kDims > 0 && !requires { Ndf<double>::kCheapLambda; };

template <template <class> class Ndf, template <class> class Fresnel, Masking kMasking = Masking::SmithUncorrelated>
struct CookTorrance {
  static constexpr bool kReciprocal = true;
  static constexpr Masking kMaskingTerm = kMasking;
  template <class T> using Distribution = Ndf<T>;
  template <class T> using FresnelTerm = Fresnel<T>;

  static ParamTable params() {
    ParamTable t = {
        {"kd", 0.0, 1.0, 0.2, Scope::PerChannel, true, "diffuse albedo of the Lambertian term kd/pi (DESIGN.md §6)"},
        {"ks", 0.0, 100.0, 0.5, Scope::PerChannel, true,
         "specular scale in ks F D G/(4 cos_i cos_o) (seed 004 Eq. 1; = 4 rho_s/pi of seed 000 Eq. 1)"}};
    for (auto& s : Ndf<double>::params()) t.push_back(s);
    for (auto& s : Fresnel<double>::params()) t.push_back(s);
    return t;
  }
  // Where the distribution's and the Fresnel term's parameters start in p.
  static constexpr int kNdfOffset = 2;
  static int fresnel_offset() {
    static const int offset = kNdfOffset + int(Ndf<double>::params().size());
    return offset;
  }

  // The masking term for unit directions above the horizon; ch = cosθh, cd = cosθd = wi·h.
  template <class T> static T masking(const Ndf<T>& ndf, const T& ci, const T& co, const T& ch, const T& cd) {
    if constexpr (kMasking == Masking::SmithUncorrelated) {
      return smith_g_uncorrelated(ndf, ci, co);
    } else if constexpr (kMasking == Masking::SmithCorrelated) {
      return smith_g_correlated(ndf, ci, co);
    } else {
      // min(1, 2 cosθh cosθo/(wo·h), 2 cosθh cosθi/(wo·h)) (DESIGN.md §4); wo·h = wi·h.
      const T g = T(2) * ch / cd;
      const T gm = ci < co ? g * ci : g * co;
      return gm < T(1) ? gm : T(1);
    }
  }

  static constexpr bool kRowMasking = kG1FromRow<Ndf> && kMasking != Masking::VGroove;
  // masking() for doubles in the batch loops: from the G1 row where the distribution has one
  // (kG1FromRow, within smith_g1_row.h's bound of masking()), masking() itself otherwise.
  static double batch_masking(const Ndf<double>& ndf, const SmithG1Row* row, double ci, double co, double ch,
                              double cd) {
    if constexpr (kRowMasking) return masking_of_g1(row->g1(ci), row->g1(co));
    else return masking(ndf, ci, co, ch, cd);
  }
  // The Smith masking term from G1 of wi and wo.
  static double masking_of_g1(double gi, double go) {
    if constexpr (kMasking == Masking::SmithUncorrelated) return gi * go;
    else return gi > 0 && go > 0 ? 1 / (1 / gi + 1 / go - 1) : 0.0;  // 1/(1 + Λi + Λo), Λ = 1/G1 − 1
  }

  static constexpr bool kDFromBlock = requires(const Ndf<double>& d, const double* c, double* o) { d.D_block(c, o); };

  // One output of a batch loop: kd/π, ks and the Fresnel term that output uses (the distribution
  // and the masking are shared by all of them).
  struct Lobe {
    double kd_pi, ks;
    Fresnel<double> fresnel;
  };

  // The batch loop with N = 1, 2 or 3 outputs (out1 unused for N = 1, out2 for N < 3): block_loop
  // where the distribution evaluates D on a block of cosines with vector math (ndf/d_block.h),
  // fused_loop otherwise.
  template <int N>
  static void batch_loop(const double* p, const Lobe (&lobes)[N], std::size_t n, const double* __restrict wix,
                         const double* __restrict wiy, const double* __restrict wiz, const double* __restrict wox,
                         const double* __restrict woy, const double* __restrict woz, double* __restrict out0,
                         double* __restrict out1, double* __restrict out2) {
    if constexpr (kDFromBlock) block_loop<N>(p, lobes, n, wix, wiy, wiz, wox, woy, woz, out0, out1, out2);
    else fused_loop<N>(p, lobes, n, wix, wiy, wiz, wox, woy, woz, out0, out1, out2);
  }

  // batch_loop in one pass: eval_at's body without its early return, every product in eval_at's
  // order, so each output equals eval_at to the bit (up to the G1 row where Λ is numeric, see
  // batch_masking).
  // Every lane computes and the horizon test selects at the end; `&` (not `&&`) keeps the loads of
  // wi_z and wo_z unconditional: a short-circuit test makes GCC sink the wo_z load under a branch,
  // and a load that "could trap" blocks if-conversion and leaves the loop scalar (DESIGN.md §12;
  // check: bench/bench_model_eval.cpp). `flatten` inlines the distribution, masking and Fresnel
  // calls whatever GCC's inlining budget decides elsewhere: a call left in the body keeps the
  // loop scalar too.
  template <int N>
  [[gnu::flatten]] static void fused_loop(const double* p, const Lobe (&lobes)[N], std::size_t n,
                                          const double* __restrict wix, const double* __restrict wiy,
                                          const double* __restrict wiz, const double* __restrict wox,
                                          const double* __restrict woy, const double* __restrict woz,
                                          double* __restrict out0, double* __restrict out1,
                                          double* __restrict out2) {
    const Ndf<double> ndf(p + kNdfOffset);
    const SmithG1Row* row = nullptr;
    if constexpr (kG1FromRow<Ndf> && kMasking != Masking::VGroove) row = &smith_g1_row(ndf);
    for (std::size_t k = 0; k < n; ++k) {
      const double ix = wix[k], iy = wiy[k], iz = wiz[k], ox = wox[k], oy = woy[k], oz = woz[k];
      const bool above = (iz > 0.0) & (oz > 0.0);
      const double hx = ix + ox, hy = iy + oy, hz = iz + oz;
      const double len = std::sqrt(hx * hx + hy * hy + hz * hz);
      const double ch = hz / len, cd = 0.5 * len;
      const double d = ndf.D(ch), g = batch_masking(ndf, row, iz, oz, ch, cd), den = 4.0 * iz * oz;
      out0[k] = lobe_value(lobes[0], above, cd, d, g, den);
      if constexpr (N >= 2) out1[k] = lobe_value(lobes[1], above, cd, d, g, den);
      if constexpr (N == 3) out2[k] = lobe_value(lobes[2], above, cd, d, g, den);
    }
  }

  // batch_loop for a distribution with D_block: per block of kDBlock pairs, the cosines, then D for
  // the whole block with vector math, then masking, Fresnel and the sum in eval_at's order. D differs
  // from eval_at's within ndf/d_block.h's bound (1e-12 relative); the rest is as in fused_loop. The
  // last block is padded with cosθh = 1, so every value is computed the same way wherever it lies.
  template <int N>
  static void block_loop(const double* p, const Lobe (&lobes)[N], std::size_t n, const double* __restrict wix,
                         const double* __restrict wiy, const double* __restrict wiz, const double* __restrict wox,
                         const double* __restrict woy, const double* __restrict woz, double* __restrict out0,
                         double* __restrict out1, double* __restrict out2) {
    const Ndf<double> ndf(p + kNdfOffset);
    const SmithG1Row* row = nullptr;
    if constexpr (kRowMasking) row = &smith_g1_row(ndf);
    alignas(64) double ch[kDBlock], cd[kDBlock], d[kDBlock];
    // With a G1 row: the cosines of wi and wo, then G1 of each, for the whole block at once.
    alignas(64) double ci[kRowMasking ? kDBlock : 1], co[kRowMasking ? kDBlock : 1];
    alignas(64) double gi[kRowMasking ? kDBlock : 1], go[kRowMasking ? kDBlock : 1];
    for (std::size_t start = 0; start < n; start += kDBlock) {
      const std::size_t m = std::min(kDBlock, n - start);
      for (std::size_t k = 0; k < m; ++k) {
        const std::size_t j = start + k;
        const double hx = wix[j] + wox[j], hy = wiy[j] + woy[j], hz = wiz[j] + woz[j];
        const double len = std::sqrt(hx * hx + hy * hy + hz * hz);
        ch[k] = hz / len;
        cd[k] = 0.5 * len;
      }
      std::fill(ch + m, ch + kDBlock, 1.0);
      ndf.D_block(ch, d);
      if constexpr (kRowMasking) {
        std::copy(wiz + start, wiz + start + m, ci);
        std::copy(woz + start, woz + start + m, co);
        std::fill(ci + m, ci + kDBlock, 1.0);
        std::fill(co + m, co + kDBlock, 1.0);
        row->g1_block(ci, gi);
        row->g1_block(co, go);
      }
      for (std::size_t k = 0; k < m; ++k) {
        const std::size_t j = start + k;
        const double iz = wiz[j], oz = woz[j];
        const bool above = (iz > 0.0) & (oz > 0.0);
        double g;
        if constexpr (kRowMasking) g = masking_of_g1(gi[k], go[k]);
        else g = masking(ndf, iz, oz, ch[k], cd[k]);
        const double den = 4.0 * iz * oz;
        out0[j] = lobe_value(lobes[0], above, cd[k], d[k], g, den);
        if constexpr (N >= 2) out1[j] = lobe_value(lobes[1], above, cd[k], d[k], g, den);
        if constexpr (N == 3) out2[j] = lobe_value(lobes[2], above, cd[k], d[k], g, den);
      }
    }
  }

  // One output of the batch loops from the shared terms, eval_at's arithmetic in eval_at's order.
  static double lobe_value(const Lobe& l, bool above, double cd, double d, double g, double den) {
    return above ? l.kd_pi + l.ks * (l.fresnel.eval(cd) * d * g / den) : 0.0;  // seed 004 Eq. 1
  }

  // ρ at one direction pair from prepared terms (kd_pi = kd/π). Both directions must be unit.
  template <class T>
  static T eval_at(const T& kd_pi, const T& ks, const Ndf<T>& ndf, const Fresnel<T>& fresnel, const T& wix,
                   const T& wiy, const T& wiz, const T& wox, const T& woy, const T& woz) {
    using std::sqrt;
    if (!(wiz > T(0) && woz > T(0))) return T(0);
    const T hx = wix + wox, hy = wiy + woy, hz = wiz + woz;
    const T len = sqrt(hx * hx + hy * hy + hz * hz);
    const T ch = hz / len;
    // |wi + wo| = 2 cos θd for unit directions: symmetric in wi and wo, so ρ(wi, wo) = ρ(wo, wi)
    // to the last bit, and one square root serves θh and θd.
    const T cd = T(0.5) * len;
    const T spec = fresnel.eval(cd) * ndf.D(ch) * masking(ndf, wiz, woz, ch, cd) / (T(4) * wiz * woz);  // seed 004 Eq. 1
    return kd_pi + ks * spec;
  }

  template <class T> static T eval(const T* p, int, const Vec3<T>& wi, const Vec3<T>& wo) {
    const Ndf<T> ndf(p + kNdfOffset);
    const Fresnel<T> fresnel(p + fresnel_offset());
    return eval_at(T(p[0] * T(kInvPi)), p[1], ndf, fresnel, wi.x(), wi.y(), wi.z(), wo.x(), wo.y(), wo.z());
  }

  // The batch loops' output for channel values p with the Fresnel term's parameters at fp.
  static Lobe lobe(const double* p, const double* fp) { return {p[0] * kInvPi, p[1], Fresnel<double>(fp)}; }

  // ρ of one channel at n direction pairs given as structure-of-arrays; out[k] for pair k, the
  // values of eval_at (to the bit, or within the bounds fused_loop and block_loop state).
  static void eval_batch(const double* p, int, std::size_t n, const double* wix, const double* wiy,
                         const double* wiz, const double* wox, const double* woy, const double* woz, double* out) {
    const Lobe lobes[1] = {lobe(p, p + fresnel_offset())};
    if (lobes[0].ks == 0.0) {
      // The diffuse term alone: variable projection's diffuse basis (fit/engine/projected_objective.h)
      // is this model at ks = 0, filled once per fit level, and needs no D or G. Equal to eval_at
      // wherever the specular term is finite (ks · x = ±0 then).
      for (std::size_t k = 0; k < n; ++k) out[k] = (wiz[k] > 0.0) & (woz[k] > 0.0) ? lobes[0].kd_pi : 0.0;
      return;
    }
    batch_loop<1>(p, lobes, n, wix, wiy, wiz, wox, woy, woz, out, nullptr, nullptr);
  }
  // eval_batch of the three channels (Model::eval_batch_rgb): one pass computing D, G and the
  // cosines once where the channels share the distribution's parameters, each output equal to its
  // channel's eval_batch to the bit; three eval_batch calls otherwise.
  static void eval_batch_rgb(const double* const p[3], std::size_t n, const double* wix, const double* wiy,
                             const double* wiz, const double* wox, const double* woy, const double* woz,
                             double* const out[3]) {
    const int f0 = fresnel_offset();
    const std::size_t bytes = sizeof(double) * std::size_t(f0 - kNdfOffset);  // bitwise: −0 ≠ +0, NaN = NaN
    const bool shared = std::memcmp(p[0] + kNdfOffset, p[1] + kNdfOffset, bytes) == 0 &&
                        std::memcmp(p[0] + kNdfOffset, p[2] + kNdfOffset, bytes) == 0;
    if (!shared) {
      for (int c = 0; c < 3; ++c) eval_batch(p[c], c, n, wix, wiy, wiz, wox, woy, woz, out[c]);
      return;
    }
    const Lobe lobes[3] = {lobe(p[0], p[0] + f0), lobe(p[1], p[1] + f0), lobe(p[2], p[2] + f0)};
    batch_loop<3>(p[0], lobes, n, wix, wiy, wiz, wox, woy, woz, out[0], out[1], out[2]);
  }
  // eval_batch at two values a, b of one Fresnel parameter (models/paired_evaluation.h): D, G and the
  // cosines once, the Fresnel term twice, both outputs equal to eval_batch's to the bit. False
  // (nothing written) for a parameter outside the Fresnel term.
  static bool eval_batch_pair(const double* p, int, int param, double a, double b, std::size_t n, const double* wix,
                              const double* wiy, const double* wiz, const double* wox, const double* woy,
                              const double* woz, double* out_a, double* out_b) {
    static const int fresnel_count = int(Fresnel<double>::params().size());
    const int f0 = fresnel_offset();
    if (param < f0 || param >= f0 + fresnel_count) return false;
    double fp_a[8], fp_b[8];  // the Fresnel term's parameters (Schlick: 1; conductors: a few)
    if (fresnel_count > 8) return false;
    std::copy(p + f0, p + f0 + fresnel_count, fp_a);
    std::copy(p + f0, p + f0 + fresnel_count, fp_b);
    fp_a[param - f0] = a;
    fp_b[param - f0] = b;
    const Lobe lobes[2] = {lobe(p, fp_a), lobe(p, fp_b)};
    batch_loop<2>(p, lobes, n, wix, wiy, wiz, wox, woy, woz, out_a, out_b, nullptr);
    return true;
  }
  static void eval_batch(const double* p, int c, const SampleSet& s, double* out) {
    eval_batch(p, c, s.size(), s.wi_x.data(), s.wi_y.data(), s.wi_z.data(), s.wo_x.data(), s.wo_y.data(),
               s.wo_z.data(), out);
  }

  // Probability of sampling the specular lobe: proportional to an albedo estimate of each lobe
  // (seed 004 §5.5's lobe selection; seed 000 §4.5): kd for the diffuse term, ks F(cosθo) for
  // the specular one (a normalized D with G ≈ 1 reflects ks F). Both are clamped at 0 (a
  // Bagher Fresnel term can be negative); with no estimate at all, the lobes share evenly.
  static double specular_probability(const double* p, const Vec3d& wo) {
    const double d = std::max(0.0, p[0]);
    const double s = std::max(0.0, p[1] * Fresnel<double>(p + fresnel_offset()).eval(wo.z()));
    if (!(d + s > 0) || !std::isfinite(d + s)) return 0.5;
    return s / (d + s);
  }

  // Diffuse: cosine hemisphere. Specular: m from the distribution (density D cosθm), wi = the
  // mirror of wo about m; draws with wo·m ≤ 0 or wi below the horizon are rejected.
  static std::optional<Vec3d> sample(const double* p, int, const Vec3d& wo, const Vec2d& u, double u_lobe) {
    if (!(wo.z() > 0)) return std::nullopt;
    if (!(u_lobe < specular_probability(p, wo))) {
      const Vec3d wi = square_to_cosine_hemisphere(u);
      if (!(wi.z() > 0)) return std::nullopt;
      return wi;
    }
    const Vec3d m = Ndf<double>(p + kNdfOffset).sample(u);
    if (!(wo.dot(m) > 0)) return std::nullopt;
    const Vec3d wi = reflect(wo, m);
    if (!(wi.z() > 0)) return std::nullopt;
    return wi;
  }

  // Mixture density (DESIGN.md §6): p_d cosθi/π + p_s D(h) cosθh / (4 |wo·h|).
  static double pdf(const double* p, int, const Vec3d& wo, const Vec3d& wi) {
    if (!(wo.z() > 0 && wi.z() > 0)) return 0.0;
    const double ps = specular_probability(p, wo);
    double v = (1.0 - ps) * wi.z() * kInvPi;
    if (ps > 0) {
      const Vec3d sum = wi + wo;
      const double len = sum.norm();
      if (len > 0) {
        const Vec3d h = sum / len;
        const double oh = wo.dot(h);
        if (oh > 0) v += ps * Ndf<double>(p + kNdfOffset).pdf(h) / (4.0 * oh);
      }
    }
    return v;
  }
};

}  // namespace brdfkit
