// Analyses on the shared real measurements (skipped when ../shared/data is absent): back-scattering
// fits on the MERL pink-felt slice and the glossy RGL films (seed 000 Fig. 3's claim), the
// tabulated-NDF model against single-lobe Cook-Torrance/Beckmann under `ngan`, and the
// diffraction map and Fresnel extraction on one RGL material.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "brdfkit/analysis/albedo_curve.h"
#include "brdfkit/analysis/backscatter.h"
#include "brdfkit/measured/diffraction_map.h"
#include "brdfkit/analysis/fresnel_extraction.h"
#include "brdfkit/analysis/ndf_estimation.h"
#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/fit/engine/fit_model.h"
#include "brdfkit/measured/load.h"
#include "support/test_util.h"

namespace brdfkit {
namespace {

const std::vector<std::string> kRgl = {"paper_white", "colodur_napoli_4f", "satin_rosaline", "vch_golden_yellow",
                                       "cc_ibiza_sunset"};
const std::vector<std::string> kGlossyRgl = {"satin_rosaline", "vch_golden_yellow", "cc_ibiza_sunset"};

std::filesystem::path rgl(const std::string& name) { return test::data_dir() / "rgl" / (name + "_rgb.bsdf"); }

void print_backscatter(const std::string& name, const analysis::BackscatterAnalysis& a) {
  for (const auto& f : a.fits)
    std::printf("  %-22s %-18s err_linear %.5f  err_log %.4f\n", name.c_str(), f.family.c_str(), f.mean_error_linear,
                f.mean_error_log);
  for (const auto& f : a.fits)
    for (size_t c = 0; c < 3; ++c) {
      std::printf("    %-18s ch%zu rho_d %.4f Fr %.4f shape", f.family.c_str(), c, f.rho_d[c], f.fr[c]);
      for (double v : f.shape[c]) std::printf(" %.4f", v);
      std::printf("\n");
    }
}

const analysis::BackscatterFit& fit_of(const analysis::BackscatterAnalysis& a, const std::string& family) {
  for (const auto& f : a.fits)
    if (f.family == family) return f;
  throw std::runtime_error("no fit " + family);
}

// A family fits no worse than its special case: SGD with p = 0 is Beckmann with m² = α (ndf/sgd.h),
// so in the space the fit minimizes SGD's error is ≤ Beckmann's in every channel.
void expect_sgd_not_worse_than_beckmann(const analysis::BackscatterAnalysis& a, const std::string& name) {
  const auto& sgd = fit_of(a, "sgd");
  const auto& beck = fit_of(a, "beckmann");
  for (size_t c = 0; c < 3; ++c) {
    const double es = a.space == analysis::SliceFitSpace::Linear ? sgd.error_linear[c] : sgd.error_log[c];
    const double eb = a.space == analysis::SliceFitSpace::Linear ? beck.error_linear[c] : beck.error_log[c];
    EXPECT_LE(es, eb * (1 + 1e-6)) << name << " channel " << c;
  }
}

TEST(Backscatter, PinkFeltSliceReportsEveryFamily) {
  BRDFKIT_REQUIRE_DATA("merl-slices");
  const auto data = load_measured(test::data_dir() / "merl-slices" / "pink-felt-1d.alta");
  for (auto space : {analysis::SliceFitSpace::Linear, analysis::SliceFitSpace::Log}) {
    analysis::BackscatterOptions opt;
    opt.space = space;
    const auto a = analysis::analyze_backscatter(*data, opt);
    std::printf("pink-felt back-scattering slice, %zu angles, fit space %s\n", a.slice.theta_h.size(),
                space == analysis::SliceFitSpace::Linear ? "linear (Eq. 12)" : "log");
    print_backscatter("pink-felt", a);
    ASSERT_EQ(a.fits.size(), opt.families.size());
    for (const auto& f : a.fits) {
      EXPECT_TRUE(std::isfinite(f.mean_error_linear) && std::isfinite(f.mean_error_log)) << f.family;
      // A fit can be no worse than its constant part alone: every family reaches < 20 % RMS of the peak.
      EXPECT_LT(f.mean_error_linear, 0.2) << f.family;
    }
    expect_sgd_not_worse_than_beckmann(a, "pink-felt");
  }
}

TEST(Backscatter, GlossyRglMaterialsReportEveryFamily) {
  BRDFKIT_REQUIRE_DATA("rgl");
  int sgd_beats_both = 0;
  for (const auto& name : kGlossyRgl) {
    const auto data = load_measured(rgl(name));
    analysis::BackscatterOptions opt;
    opt.space = analysis::SliceFitSpace::Log;
    opt.families = {"beckmann", "ggx", "sgd"};  // the comparison of seed 000 Fig. 3 (CI time: the others are on pink-felt)
    const auto a = analysis::analyze_backscatter(*data, opt);
    std::printf("%s back-scattering slice (RGL evaluated at wi = wo), %zu angles, log fit\n", name.c_str(),
                a.slice.theta_h.size());
    print_backscatter(name, a);
    const double sgd = fit_of(a, "sgd").mean_error_log, beck = fit_of(a, "beckmann").mean_error_log,
                 ggx = fit_of(a, "ggx").mean_error_log;
    EXPECT_TRUE(std::isfinite(sgd) && std::isfinite(beck) && std::isfinite(ggx));
    expect_sgd_not_worse_than_beckmann(a, name);
    // Seed 000 Fig. 3: SGD follows the measured back-scattering better than both classic
    // families. Measured here (log space, mean over R, G, B): satin_rosaline 0.266 vs Beckmann
    // 0.284, GGX 0.341; vch_golden_yellow 0.557 vs 0.621, 0.783; cc_ibiza_sunset 0.745 vs 0.844, 1.226.
    EXPECT_LT(sgd, beck) << name;
    EXPECT_LT(sgd, ggx) << name;
    sgd_beats_both += sgd < beck && sgd < ggx;
  }
  std::printf("SGD beats Beckmann and GGX on %d of %zu glossy RGL materials (log-space slice fit)\n", sgd_beats_both,
              kGlossyRgl.size());
  EXPECT_EQ(sgd_beats_both, int(kGlossyRgl.size()));
}

TEST(TabulatedNdf, BeatsCookTorranceBeckmannOnMostRealMaterials) {
  BRDFKIT_REQUIRE_DATA("rgl");
  const Model& ct = model_by_name("cook-torrance");
  const Model& ctb = model_by_name("cook-torrance-beckmann");
  // RGL tables on a 3-degree grid; the Cornell files on their own samples (fit/metric_samples.h).
  std::vector<std::pair<std::string, std::filesystem::path>> files;
  for (const auto& name : kRgl) files.emplace_back(name, rgl(name));
  for (const std::string name : {"acryl_blue", "garnet_red", "krylon_blue"})
    if (std::filesystem::exists(test::data_dir() / "cornell" / (name + ".brdf")))
      files.emplace_back(name, test::data_dir() / "cornell" / (name + ".brdf"));
  int better = 0;
  for (const auto& [name, path] : files) {
    const auto data = load_measured(path);
    const fit::Metric metric = fit::make_metric("ngan", *data, {3});  // 3-degree grid: CI time, same grid for all
    analysis::NdfEstimationOptions opt;
    opt.f0 = 0.05;  // given (seed 002 §5.1 allows it): the Brent search over F0 is the CLI's default
    const analysis::NdfEstimate e = analysis::estimate_tabulated_ndf(metric, opt);
    const analysis::TabulatedCookTorrance model = e.model();
    const double tab = metric.value(model, e.values);
    const double e_ct = fit::fit_model(ct, metric, {}).metric_value;
    const double e_ctb = fit::fit_model(ctb, metric, {}).metric_value;
    std::printf("  %-20s ngan (%s): tabulated %.5f (F0 %.3f, %d it.)  cook-torrance %.5f  "
                "cook-torrance-beckmann %.5f\n",
                name.c_str(), metric.on_samples() ? "own samples" : "3-degree grid", tab, e.f0, e.iterations, e_ct, e_ctb);
    EXPECT_NEAR(tab, e.residual_history.back(), 1e-6 * std::max(1.0, tab));  // the estimate's own residual is the metric
    better += tab < std::min(e_ct, e_ctb);
  }
  std::printf("tabulated NDF beats both single-lobe Beckmann Cook-Torrance fits on %d of %zu real materials\n", better,
              files.size());
  EXPECT_GT(better, int(files.size()) / 2);
}

TEST(Diffraction, MapOnRglHasCountsVarianceAndFraction) {
  BRDFKIT_REQUIRE_DATA("rgl");
  const auto data = load_measured(rgl("satin_rosaline"));
  DiffractionOptions opt;
  opt.theta_h_cells = opt.theta_d_cells = 30;
  opt.phi_d_samples = 24;
  const auto map = diffraction_map(*data, opt);
  int with_data = 0;
  for (const auto& c : map.cells) {
    with_data += c.count > 0;
    EXPECT_LE(c.count, opt.phi_d_samples);
    EXPECT_TRUE((c.variance >= 0).all());
  }
  std::printf("satin_rosaline diffraction map 30x30: %d cells with data; diffraction-dominated fraction R %.3f G %.3f "
              "B %.3f (of %d %d %d classified)\n",
              with_data, map.diffraction_fraction[0], map.diffraction_fraction[1], map.diffraction_fraction[2],
              map.classified[0], map.classified[1], map.classified[2]);
  EXPECT_GT(with_data, 400);
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(map.classified[size_t(c)], 300);
    EXPECT_GE(map.diffraction_fraction[size_t(c)], 0.0);
    EXPECT_LE(map.diffraction_fraction[size_t(c)], 1.0);
  }
}

}  // namespace
}  // namespace brdfkit
