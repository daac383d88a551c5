// The fast path of the full-size MERL fit (DESIGN.md §12) changes no
// number it should not: each shortcut is checked against the plain computation it replaces.
//   - PairedEvaluation::eval_batch_pair (one pass for a Fresnel-paired colour's two bases) equals
//     two eval_batch calls, for every parameter of every registered model that offers it;
//   - the Cook-Torrance batch loops equal eval<double>: to the bit, or within the G1 row's bound
//     where they read G1 from a row (models/cook_torrance.h);
//   - Cook-Torrance's eval_batch_rgb (one pass for R, G and B where they share the distribution's
//     parameters) equals the three channels' eval_batch to the bit;
//   - Cook-Torrance's eval_batch at ks = 0 (the diffuse basis, without D or G) equals eval;
//   - the cell domain's directions (fit/metric/metric_cells.cpp, sines and cosines once per axis) equal
//     merl::cell_directions of every cell;
//   - a fit through the paired pass gives the same parameters, to the bit, as one through two
//     plain passes (fit/engine/projected_objective.cpp, its cache of bases included);
//   - a basis no variable moves is shared by the channels only where they agree on it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "support/merl_cases.h"
#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/fit/metric/metric_cells.h"
#include "brdfkit/fit/metric/metric_definition.h"
#include "brdfkit/fit/engine/fit_model.h"
#include "brdfkit/fit/procedure/retabled_model.h"
#include "brdfkit/measured/merl.h"
#include "brdfkit/measured/merl_brdf.h"
#include "brdfkit/models/cook_torrance_catalogue.h"
#include "brdfkit/models/model.h"
#include "brdfkit/models/paired_evaluation.h"

namespace brdfkit {
namespace {

// Direction pairs above the horizon with θ from 0 to 89.5° on both sides (SoA), seeded.
struct Pairs {
  std::vector<double> v[6];
  SoaPairs soa() const { return {v[0].data(), v[1].data(), v[2].data(), v[3].data(), v[4].data(), v[5].data()}; }
  size_t size() const { return v[0].size(); }
  void add(const Vec3d& wi, const Vec3d& wo) {
    for (int a = 0; a < 3; ++a) {
      v[a].push_back(wi[a]);
      v[3 + a].push_back(wo[a]);
    }
  }
};

Pairs random_pairs(size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  Pairs p;
  for (size_t k = 0; k < n; ++k) {
    const double ti = std::acos(1 - u(rng) * (1 - std::cos(1.562))), to = std::acos(1 - u(rng) * (1 - std::cos(1.562)));
    p.add(spherical_direction(ti, 0.0), spherical_direction(to, 2 * kPi * u(rng)));
  }
  return p;
}

bool same_bits(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

TEST(SpeedPath, PairEvaluationEqualsTwoBatchCalls) {
  const Pairs pairs = random_pairs(400, 3);
  int custom = 0, checked = 0;
  for (const Model* m : all_models()) {
    const auto* paired = dynamic_cast<const PairedEvaluation*>(m);
    if (!paired) continue;
    const ParamTable& t = m->params();
    const ParamValues v = ParamValues::defaults(t);
    for (size_t p = 0; p < t.size(); ++p) {
      if (!std::isfinite(t[p].lower) || !std::isfinite(t[p].upper)) continue;
      const double a = t[p].lower, b = 0.3 * t[p].lower + 0.7 * t[p].upper;
      for (int c = 0; c < 3; ++c) {
        std::vector<double> pa = v.values[size_t(c)], pb = pa;
        pa[p] = a;
        pb[p] = b;
        std::vector<double> want_a(pairs.size()), want_b(pairs.size()), got_a(pairs.size()), got_b(pairs.size());
        m->eval_batch(pa.data(), c, pairs.size(), pairs.soa(), want_a.data());
        m->eval_batch(pb.data(), c, pairs.size(), pairs.soa(), want_b.data());
        if (!paired->eval_batch_pair(v.channel(c), c, int(p), a, b, pairs.size(), pairs.soa(), got_a.data(),
                                     got_b.data()))
          continue;
        for (size_t k = 0; k < pairs.size(); ++k) {
          ASSERT_TRUE(same_bits(got_a[k], want_a[k])) << m->name() << " " << t[p].name << " pair " << k;
          ASSERT_TRUE(same_bits(got_b[k], want_b[k])) << m->name() << " " << t[p].name << " pair " << k;
        }
        ++checked;
      }
      if (t[p].name == "F0" && m->name().starts_with("cook-torrance")) ++custom;
    }
  }
  std::printf("eval_batch_pair: %d (model, parameter, channel) cases bit-equal; %d Cook-Torrance F0 parameters\n",
              checked, custom);
  EXPECT_GE(custom, 11);  // every registered Cook-Torrance model has a Schlick F0
}

// Variable projection's diffuse basis is the model at ks = 0, which eval_batch computes without D
// or G (models/cook_torrance.h): for every registered Cook-Torrance model, kd/π above the horizon
// and 0 below it, to the bit, and eval's value at every pair.
TEST(SpeedPath, CookTorranceAtZeroKsIsTheDiffuseTermAlone) {
  Pairs pairs = random_pairs(300, 5);
  pairs.add(Vec3d(0.6, 0.0, -0.8), Vec3d(0.0, 0.0, 1.0));  // wi below the horizon
  pairs.add(Vec3d(0.0, 0.0, 1.0), Vec3d(0.0, 0.6, -0.8));  // wo below
  int models = 0;
  for (const Model* m : all_models()) {
    if (!m->name().starts_with("cook-torrance")) continue;
    const ParamTable& t = m->params();
    ParamValues v = ParamValues::defaults(t);
    v.set(t, "kd", 0.3);
    v.set(t, "ks", 0.0);
    std::vector<double> got(pairs.size());
    m->eval_batch(v.channel(1), 1, pairs.size(), pairs.soa(), got.data());
    for (size_t k = 0; k < pairs.size(); ++k) {
      const Vec3d wi(pairs.v[0][k], pairs.v[1][k], pairs.v[2][k]), wo(pairs.v[3][k], pairs.v[4][k], pairs.v[5][k]);
      const double want = wi.z() > 0 && wo.z() > 0 ? 0.3 * kInvPi : 0.0;
      ASSERT_TRUE(same_bits(got[k], want)) << m->name() << " pair " << k << ": " << got[k];
      ASSERT_TRUE(same_bits(got[k], m->eval(v.channel(1), 1, wi, wo))) << m->name() << " pair " << k;
    }
    ++models;
  }
  std::printf("%d Cook-Torrance models at ks = 0: kd/pi above the horizon, 0 below, eval's value\n", models);
  EXPECT_GE(models, 11);
}

// Every registered Cook-Torrance model's batch loop (paired or not) against eval<double> at random
// pairs: to the bit where G1 has a closed form the loop uses (GGX) or masking is V-groove, and D
// is eval's; within D_block's 1e-12 relative (ndf/d_block.h) where D comes from a block and G1 is
// still eval's (Beckmann, whose Λ has a closed form); within the G1 row's bound where the loop
// reads G1 from a row (shadowing/smith_g1_row.h: |ΔG1| ≤ 1e-6, so the product of two G1 is within
// 2e-6 relative of eval's; D_block's 1e-12 is far inside that bound).
template <class M> void expect_batch_equals_eval(int& exact, int& block, int& row) {
  const ParamTable t = M::params();
  const Pairs pairs = random_pairs(400, 9);
  ParamValues v = ParamValues::defaults(t);
  v.set(t, "kd", 0.1);
  v.set(t, "ks", 0.8);
  const double* p = v.channel(0);
  const int f0 = find_param(t, "F0");
  std::vector<double> batch(pairs.size()), pa(pairs.size()), pb(pairs.size());
  M::eval_batch(p, 0, pairs.size(), pairs.v[0].data(), pairs.v[1].data(), pairs.v[2].data(), pairs.v[3].data(),
                pairs.v[4].data(), pairs.v[5].data(), batch.data());
  ASSERT_TRUE(M::eval_batch_pair(p, 0, f0, 0.0, 1.0, pairs.size(), pairs.v[0].data(), pairs.v[1].data(),
                                 pairs.v[2].data(), pairs.v[3].data(), pairs.v[4].data(), pairs.v[5].data(), pa.data(),
                                 pb.data()));
  std::vector<double> q0(p, p + t.size()), q1 = q0;
  q0[size_t(f0)] = 0.0;
  q1[size_t(f0)] = 1.0;
  constexpr bool kFromRow = kG1FromRow<M::template Distribution> && M::kMaskingTerm != Masking::VGroove;
  constexpr bool kDFromBlock = requires(const typename M::template Distribution<double>& d, const double* c, double* o) {
    d.D_block(c, o);
  };
  for (size_t k = 0; k < pairs.size(); ++k) {
    const Vec3d wi(pairs.v[0][k], pairs.v[1][k], pairs.v[2][k]), wo(pairs.v[3][k], pairs.v[4][k], pairs.v[5][k]);
    const double got[3] = {batch[k], pa[k], pb[k]};
    const double want[3] = {M::template eval<double>(p, 0, wi, wo), M::template eval<double>(q0.data(), 0, wi, wo),
                            M::template eval<double>(q1.data(), 0, wi, wo)};
    for (int j = 0; j < 3; ++j) {
      const double lobe = want[j] - 0.1 * kInvPi;  // the specular part carries the G1 and D errors
      if (kFromRow) {
        ASSERT_NEAR(got[j], want[j], 2e-6 * std::abs(lobe) + 1e-15) << M::name() << " pair " << k;
      } else if (kDFromBlock) {
        ASSERT_NEAR(got[j], want[j], 1e-12 * std::abs(lobe) + 1e-15) << M::name() << " pair " << k;
      } else {
        ASSERT_TRUE(same_bits(got[j], want[j])) << M::name() << " pair " << k;
      }
    }
  }
  ++(kFromRow ? row : kDFromBlock ? block : exact);
}

TEST(SpeedPath, CookTorranceBatchLoopsEqualEval) {
  int exact = 0, block = 0, row = 0;
  std::apply([&](auto... m) { (expect_batch_equals_eval<decltype(m)>(exact, block, row), ...); },
             CookTorranceCatalogue{});
  std::printf("Cook-Torrance batch loops: %d models bit-equal to eval<double>, %d within D_block's bound, %d within "
              "the G1 row's bound\n",
              exact, block, row);
  EXPECT_EQ(exact + block + row, int(std::tuple_size_v<CookTorranceCatalogue>));
  EXPECT_GE(row, 9);
}

// eval_batch_rgb against eval_batch per channel, to the bit: channels that differ in kd, ks and F0
// and share the distribution's parameters (one pass), then channels whose first distribution
// parameter differs (three passes).
template <class M> void expect_rgb_batch_equals_channels() {
  const ParamTable t = M::params();
  const Pairs pairs = random_pairs(300, 11);
  ParamValues v = ParamValues::defaults(t);
  const double kd[3] = {0.1, 0.3, 0.02}, ks[3] = {0.8, 0.2, 1.5}, f0[3] = {0.04, 0.5, 0.9};
  for (int c = 0; c < 3; ++c) {
    v.values[size_t(c)][size_t(find_param(t, "kd"))] = kd[c];
    v.values[size_t(c)][size_t(find_param(t, "ks"))] = ks[c];
    v.values[size_t(c)][size_t(find_param(t, "F0"))] = f0[c];
  }
  for (bool shared : {true, false}) {
    if (!shared) v.values[2][size_t(M::kNdfOffset)] *= 1.25;
    std::vector<double> rgb[3], one(pairs.size());
    for (auto& r : rgb) r.resize(pairs.size());
    const double* const p[3] = {v.channel(0), v.channel(1), v.channel(2)};
    double* const out[3] = {rgb[0].data(), rgb[1].data(), rgb[2].data()};
    M::eval_batch_rgb(p, pairs.size(), pairs.v[0].data(), pairs.v[1].data(), pairs.v[2].data(), pairs.v[3].data(),
                      pairs.v[4].data(), pairs.v[5].data(), out);
    for (int c = 0; c < 3; ++c) {
      M::eval_batch(p[c], c, pairs.size(), pairs.v[0].data(), pairs.v[1].data(), pairs.v[2].data(),
                    pairs.v[3].data(), pairs.v[4].data(), pairs.v[5].data(), one.data());
      for (size_t k = 0; k < pairs.size(); ++k)
        ASSERT_TRUE(same_bits(rgb[c][k], one[k]))
            << M::name() << (shared ? " shared shape" : " per-channel shape") << " channel " << c << " pair " << k
            << ": " << rgb[c][k] << " vs " << one[k];
    }
  }
}

TEST(SpeedPath, CookTorranceRgbBatchEqualsChannelBatches) {
  std::apply([&](auto... m) { (expect_rgb_batch_equals_channels<decltype(m)>(), ...); }, CookTorranceCatalogue{});
}

// Every sample of the cell domain, in its order, against merl::cell_directions of its cell.
void check_cell_domain(int coarsen, bool fold) {
  merl::Table table;
  for (size_t off = 0; off < merl::kCellCount; ++off) table.set_raw(off, 1.0, 2.0, 3.0);
  fit::CellWeighting w = fit::ngan_metric(coarsen).cells;
  w.fold = fold;
  const fit::CellDomain d = fit::build_cell_domain(table, w, coarsen);
  const int k = coarsen, nh = merl::kResThetaH / k, nd = merl::kResThetaD / k, np = merl::kResPhiD / k;
  const int blocks_d = (nd + 14) / 15;
  ASSERT_EQ(d.chunks.size(), size_t(nh * blocks_d));
  size_t samples = 0;
  for (size_t i = 0; i < d.chunks.size(); ++i) {
    const fit::MetricChunk& ch = d.chunks[i];
    const int bh = int(i) / blocks_d, bd0 = int(i) % blocks_d * 15;
    size_t s = 0;
    auto expect = [&](const Vec3d& wi, const Vec3d& wo) {
      ASSERT_LT(s, ch.size());
      const double got[6] = {ch.wi_x[s], ch.wi_y[s], ch.wi_z[s], ch.wo_x[s], ch.wo_y[s], ch.wo_z[s]};
      const double want[6] = {wi.x(), wi.y(), wi.z(), wo.x(), wo.y(), wo.z()};
      for (int a = 0; a < 6; ++a) ASSERT_EQ(got[a], want[a]) << "chunk " << i << " sample " << s << " coordinate " << a;
      ++s;
    };
    for (int bd = bd0; bd < std::min(nd, bd0 + 15); ++bd)
      for (int bp = 0; bp < np; ++bp) {
        Vec3d wi, wo;
        if (!merl::cell_directions({bh * k + k / 2, bd * k + k / 2, bp * k + k / 2}, wi, wo)) continue;
        const double mu_io = w.density(wi, wo), mu_oi = w.density(wo, wi);
        if (!(mu_io > 0 || mu_oi > 0)) continue;
        if (fold) {
          expect(wi, wo);
        } else {
          if (mu_io > 0) expect(wi, wo);
          if (mu_oi > 0) expect(wo, wi);
        }
      }
    ASSERT_EQ(s, ch.size()) << "chunk " << i;
    samples += s;
  }
  std::printf("cell domain (coarsen %d, %s): %zu samples bit-equal to merl::cell_directions\n", coarsen,
              fold ? "folded" : "both orientations", samples);
}

TEST(SpeedPath, CellDomainDirectionsAreMerlCellCentres) {
  check_cell_domain(1, true);
  check_cell_domain(3, false);
}

// The runtime model without its paired evaluation: variable projection then makes two plain
// eval_batch passes for a Fresnel pair.
class WithoutPairPass final : public Model {
 public:
  explicit WithoutPairPass(const Model& m) : m_(m) {}
  std::string_view name() const override { return m_.name(); }
  std::string_view description() const override { return m_.description(); }
  const ParamTable& params() const override { return m_.params(); }
  bool reciprocal() const override { return m_.reciprocal(); }
  double eval(const double* p, int c, const Vec3d& wi, const Vec3d& wo) const override { return m_.eval(p, c, wi, wo); }
  void eval_batch(const double* p, int c, std::size_t n, const SoaPairs& d, double* out) const override {
    m_.eval_batch(p, c, n, d, out);
  }
  std::optional<Vec3d> sample(const double* p, int c, const Vec3d& wo, const Vec2d& u, double u_lobe) const override {
    return m_.sample(p, c, wo, u, u_lobe);
  }
  double pdf(const double* p, int c, const Vec3d& wo, const Vec3d& wi) const override { return m_.pdf(p, c, wo, wi); }

 private:
  const Model& m_;
};

TEST(SpeedPath, FitThroughPairedPassIsBitIdentical) {
  const Model& m = model_by_name("cook-torrance-beckmann");
  const ParamValues truth = test::with(m, {{"kd", Rgb(0.12, 0.08, 0.05)},
                                           {"ks", Rgb(0.9, 0.7, 0.6)},
                                           {"alpha", Rgb::Constant(0.12)},
                                           {"F0", Rgb(0.05, 0.3, 0.08)}});
  const MerlBrdf data(test::tabulate_cells(m, truth, 3), "speedpath.binary");
  const fit::Metric metric = fit::make_metric("ngan", data, {3});
  const fit::FitResult fast = fit::fit_model(m, metric, {});
  const WithoutPairPass plain_model(m);
  const fit::FitResult plain = fit::fit_model(plain_model, metric, {});
  EXPECT_EQ(fast.iterations, plain.iterations);
  EXPECT_EQ(fast.metric_value, plain.metric_value);
  double worst = 0;
  for (int c = 0; c < 3; ++c)
    for (size_t p = 0; p < m.params().size(); ++p) {
      EXPECT_EQ(fast.values.values[size_t(c)][p], plain.values.values[size_t(c)][p]) << m.params()[p].name << " " << c;
      const double want = truth.values[size_t(c)][p];
      worst = std::max(worst, std::abs(fast.values.values[size_t(c)][p] - want) / std::abs(want));
    }
  std::printf("paired vs plain fit: bit-identical; worst relative error vs truth %.3g (%d iterations)\n", worst,
              fast.iterations);
  EXPECT_LT(worst, 1e-9);
}

// He with its shape and index held: no variable moves the ks basis, but it differs by channel (its
// wavelength). The constant bases are computed once per stride, and a class is shared with class
// 0 only where it equals it (Lambert's kd basis): the colours are recovered exactly.
TEST(SpeedPath, HeWithItsShapeHeldKeepsItsChannelDependentBasisPerChannel) {
  const Model& he = model_by_name("he");
  ParamTable table = he.params();
  for (const auto& [name, value] : {std::pair{"sigma0", 0.4}, std::pair{"tau", 2.5}, std::pair{"eta", 1.5},
                                    std::pair{"k", 0.2}}) {
    ParamSpec& s = table[size_t(find_param(table, name))];
    s.lower = s.upper = s.def = value;
  }
  const fit::RetabledModel held(he, table);
  const ParamValues truth = test::with(he, {{"kd", Rgb(0.12, 0.08, 0.05)},
                                            {"ks", Rgb(0.9, 0.7, 0.6)},
                                            {"sigma0", Rgb::Constant(0.4)},
                                            {"tau", Rgb::Constant(2.5)},
                                            {"eta", Rgb::Constant(1.5)},
                                            {"k", Rgb::Constant(0.2)}});
  const MerlBrdf data(test::tabulate_cells(he, truth, 3), "held-he.binary");
  const fit::Metric metric = fit::make_metric("ngan", data, {3});
  const fit::FitResult r = fit::fit_model(held, metric, {});
  for (const char* name : {"kd", "ks"})
    for (int c = 0; c < 3; ++c) {
      const size_t p = size_t(find_param(he.params(), name));
      const double want = truth.values[size_t(c)][p];
      EXPECT_NEAR(r.values.values[size_t(c)][p], want, 1e-9 * want) << name << " channel " << c;
    }
}

}  // namespace
}  // namespace brdfkit
