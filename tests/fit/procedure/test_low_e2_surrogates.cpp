// Löw's smooth model under `low-e2` (seed 003 Eq. 32–33), the path where the colours are solver
// parameters because ln(1 + ·) is not linear in ρ (fit/engine/log_residual_objective.cpp), and the
// always-run part of the surrogate check: on MERL-format surrogates of published Bagher SGD fits,
// brdfkit's low-smooth fit reaches an E2 no larger than Löw's published smooth parameters'
// (bench/surrogate_acceptance.cpp runs 12 full-size materials).
// To stay within the CI budget the tables hold only the cells a 4× coarsened cell domain reads
// (one cell per 4 × 4 × 4 block of indices), and both E2 values are taken on that domain.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "brdfkit/fit/procedure/procedure.h"
#include "brdfkit/measured/merl_brdf.h"
#include "brdfkit/models/published_fits.h"
#include "support/fit_test_util.h"
#include "support/test_util.h"

namespace brdfkit::fit {
namespace {

constexpr int kCoarsen = 4;

double param(const Model& m, const ParamValues& v, const char* name, int c = 0) {
  return v.values[size_t(c)][size_t(find_param(m.params(), name))];
}

// A MERL table holding only the cells build_cell_domain reads at coarsening k (each k-block's
// middle cell), filled at the cell centre like merl::tabulate; the others are "not measured".
merl::Table sparse_table(const Brdf& brdf, int k) {
  using namespace merl;
  Table t;
  for (int h = k / 2; h < kResThetaH; h += k)
    for (int d = k / 2; d < kResThetaD; d += k)
      for (int p = k / 2; p < kResPhiD; p += k) {
        const Cell c{h, d, p};
        Vec3d wi, wo;
        if (!cell_directions(c, wi, wo)) continue;
        const Rgb v = brdf.eval(wi, wo);
        t.set_raw(cell_offset(c), v[0] / kScale[0], v[1] / kScale[1], v[2] / kScale[2]);
      }
  return t;
}

// A low-smooth material is fitted back to its own parameters under E2 from the default start
// (B 1000, C 1, η 1.5, colours from the linearized solve).
TEST(LowE2, RecoversLowSmoothFromItsMerlTable) {
  const Model& m = model_by_name("low-smooth");
  const ParamValues want = test::make_values(m, {{"kd", Rgb(0.05, 0.1, 0.15)},
                                                 {"A", Rgb(30, 20, 10)},
                                                 {"B", Rgb::Constant(400)},
                                                 {"C", Rgb::Constant(0.8)},
                                                 {"eta", Rgb::Constant(1.7)}});
  const MerlBrdf data(sparse_table(Brdf(m, want), kCoarsen), "low-smooth");
  FitSettings opt;
  opt.coarsen = kCoarsen;
  const ProcedureResult r = run_procedure(m, data, test::with_procedure(opt, "low-e2"));
  double worst = 0;
  for (const char* name : {"kd", "A", "B", "C", "eta"})
    for (int c = 0; c < 3; ++c) {
      const double e = std::abs(param(m, r.fit.values, name, c) / param(m, want, name, c) - 1);
      EXPECT_LT(e, 1e-6) << name << " channel " << c;
      worst = std::max(worst, e);
    }
  EXPECT_LT(r.fit.metric_value, 1e-16);
  std::printf("low-e2 recovery: worst relative parameter error %.2g, E2 %.3g, %d iterations\n", worst,
              r.fit.metric_value, r.fit.iterations);
}

// Issue #5: E2(brdfkit's low-e2 fit) ≤ E2(Löw's published smooth fit) on SGD surrogates. The
// materials, from bench/surrogate_acceptance.cpp's full-size table: the two whose E2 the fit
// improves least (pearl-paint 0.91×, chrome 0.73× the published E2; chrome is also the sharpest
// lobe), and the one whose published fit is farthest from its surrogate's optimum (white-paint
// 0.090×).
TEST(LowE2, FitOfSgdSurrogateReachesThePublishedSmoothE2) {
  BRDFKIT_REQUIRE_DATA("published-fits");
  const auto dir = test::data_dir() / "published-fits";
  const PublishedFits sgd = PublishedFits::read(dir / "bagher2012-sgd.json");
  const PublishedFits smooth = PublishedFits::read(dir / "low2012-smooth-E2.json");
  const Model& low = model_by_name("low-smooth");
  for (const char* material : {"pearl-paint", "chrome", "white-paint"}) {
    SCOPED_TRACE(material);
    const MerlBrdf data(sparse_table(sgd.brdf(material), kCoarsen), material);
    const Metric e2 = make_metric("low-e2", data, {kCoarsen});
    const Brdf published = smooth.brdf(material);
    const double e2_published = e2.value(published.model(), published.values());
    FitSettings opt;
    opt.coarsen = kCoarsen;
    const ProcedureResult r = run_procedure(low, data, test::with_procedure(opt, "low-e2"));
    EXPECT_LE(r.fit.metric_value, e2_published);
    // The fit's own sum is the metric's (summed in another order).
    EXPECT_NEAR(r.fit.metric_value, e2.value(low, r.fit.values), 1e-12 * r.fit.metric_value);
    std::printf("%s: E2 published %.6g, brdfkit %.6g (B %.5g C %.4g eta %.4g, %d iterations)\n", material,
                e2_published, r.fit.metric_value, param(low, r.fit.values, "B"), param(low, r.fit.values, "C"),
                param(low, r.fit.values, "eta"), r.fit.iterations);
  }
}

// Issue #5: the bagher procedure recovers a surrogate's own parameters. Three published fits have
// F1 > F0 in some channel (7 channels): Eq. 11 then gives F(θd = 0) = F0 − F1 < 0, a negative
// lobe on the θd = 0 slice that step 1 cannot fit with F ≡ 1 and Fr ≥ 0 (white-paint red came out
// α 0.0499, p 0.497 for 0.0654, 0.797). Step 1 also tries F ≡ −1 when Fr ends at 0. The table holds
// the two slices and the cells of the 8×-coarsened domain the reported metric reads.
TEST(BagherRecovery, PublishedFitsWithANegativeLobeAtNormalIncidence) {
  BRDFKIT_REQUIRE_DATA("published-fits");
  const PublishedFits sgd = PublishedFits::read(test::data_dir() / "published-fits" / "bagher2012-sgd.json");
  for (const char* material : {"white-paint", "blue-fabric", "white-fabric2"}) {
    SCOPED_TRACE(material);
    const Brdf truth = sgd.brdf(material);
    merl::Table table = sparse_table(truth, 8);
    for (int k = 0; k < merl::kResThetaH; ++k)
      for (const merl::Cell c : {merl::Cell{k, 0, merl::kResPhiD / 2}, merl::Cell{0, k, merl::kResPhiD / 2}}) {
        Vec3d wi, wo;
        if (!merl::cell_directions(c, wi, wo)) continue;
        const Rgb v = truth.eval(wi, wo);
        table.set_raw(merl::cell_offset(c), v[0] / merl::kScale[0], v[1] / merl::kScale[1], v[2] / merl::kScale[2]);
      }
    const MerlBrdf data(std::move(table), material);
    FitSettings opt;
    opt.coarsen = 8;
    const ProcedureResult r = run_procedure(truth.model(), data, test::with_procedure(opt, "bagher"));
    const Model& m = truth.model();
    double worst = 0;
    for (int c = 0; c < 3; ++c)
      for (const char* name : {"kd", "ks", "alpha", "p", "F0", "F1"}) {
        const double want = param(m, truth.values(), name, c);
        // F0 and F1 relative to the larger of the two (F0 = 1.8e-13 in white-paint blue); the
        // others relative to at least 1e-3 (white-fabric2's exponents p are ~1e-12: t^−p = 1).
        const bool fresnel = name[0] == 'F';
        const double scale = fresnel ? std::max(std::abs(param(m, truth.values(), "F0", c)),
                                                std::abs(param(m, truth.values(), "F1", c)))
                                     : std::max(std::abs(want), 1e-3);
        const double e = std::abs(param(m, r.fit.values, name, c) - want) / scale;
        EXPECT_LT(e, 1e-6) << name << " channel " << c;
        worst = std::max(worst, e);
      }
    std::printf("%s: bagher recovery, worst relative parameter error %.2g, bagher metric %.3g\n", material, worst,
                r.fit.metric_value);
  }
}

}  // namespace
}  // namespace brdfkit::fit
