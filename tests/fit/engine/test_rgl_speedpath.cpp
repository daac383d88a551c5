// The fast paths of RGL metric domains (RglBrdf::eval_row, MeasuredBrdf::eval_row) give the
// values of pair-by-pair RglBrdf::eval, and every metric's value on real RGL data is the one the
// code before these paths gave (pinned from commit 05d488f). Skipped when the data are absent.
#include <gtest/gtest.h>

#include <thread>

#include <cmath>
#include <map>
#include <random>

#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/fit/metric/metric_store.h"
#include "brdfkit/fit/metric/metric_grid.h"
#include "brdfkit/measured/rgl_tensor.h"
#include "brdfkit/models/model.h"
#include "support/test_util.h"

using namespace brdfkit;
using namespace brdfkit::fit;

namespace {

const char* const kFiles[] = {"cc_ibiza_sunset_rgb", "colodur_napoli_4f_rgb", "paper_white_rgb", "satin_rosaline_rgb",
                              "vch_golden_yellow_rgb"};

std::filesystem::path rgl_file(const std::string& stem) { return test::data_dir() / "rgl" / (stem + ".bsdf"); }

// cook-torrance-beckmann as fitted to cc_ibiza_sunset under ngan by 05d488f (`brdfkit fit`).
ParamValues ibiza_fit(const Model& model) {
  ParamValues v = ParamValues::defaults(model.params());
  const std::map<std::string, std::array<double, 3>> fitted = {
      {"kd", {0.14034950790304365, 0.056666734676645736, 0.03837817004023923}},
      {"ks", {0.8695731863043272, 1.1257578243855624, 1.106537752715415}},
      {"alpha", {0.0962490318679972, 0.0962490318679972, 0.0962490318679972}},
      {"F0", {0.190328796455758, 0.07121970803935311, 0.0551019679588596}}};
  for (size_t p = 0; p < model.params().size(); ++p)
    for (int c = 0; c < 3; ++c) v.values[size_t(c)][p] = fitted.at(model.params()[p].name)[size_t(c)];
  return v;
}

}  // namespace

// eval_row must be eval() pair by pair, bit for bit: wi with and without azimuth, at the normal,
// below the horizon; wo anywhere, including below the horizon and the mirror direction.
TEST(RglSpeedpath, EvalFromIsEvalPairByPair) {
  BRDFKIT_REQUIRE_DATA("rgl");
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (const char* name : kFiles) {
    SCOPED_TRACE(name);
    const RglBrdf b(rgl_file(name));
    for (const Vec3d& wi : {spherical_direction(0.0, 0.0), spherical_direction(0.3, 0.0), spherical_direction(1.1, 2.0),
                            spherical_direction(1.5, -0.7), Vec3d(0.6, 0.0, -0.8)}) {
      std::vector<Vec3d> wo;
      for (int k = 0; k < 400; ++k) wo.push_back(spherical_direction(u(rng) * kPi * 0.55, u(rng) * 2 * kPi));
      wo.push_back(reflect(wi, Vec3d(0, 0, 1)).normalized());
      wo.push_back(Vec3d(0, 0, 1));
      std::vector<std::optional<Rgb>> batch;
      b.eval_row(wi, wo, batch);
      ASSERT_EQ(batch.size(), wo.size());
      size_t valid = 0;
      for (size_t k = 0; k < wo.size(); ++k) {
        const auto one = b.eval(wi, wo[k]);
        ASSERT_EQ(one.has_value(), batch[k].has_value()) << k;
        if (!one) continue;
        ++valid;
        for (int c = 0; c < 3; ++c) ASSERT_EQ((*one)[c], (*batch[k])[c]) << k << " channel " << c;
      }
      EXPECT_EQ(valid > 0, wi.z() > 0);
    }
  }
}

// A metric chunk holds, for every grid node with both directions above the horizon, the value of
// RglBrdf::eval at that node, in (θo, φ) order.
TEST(RglSpeedpath, ChunkHoldsDirectLookups) {
  BRDFKIT_REQUIRE_DATA("rgl");
  const RglBrdf b(rgl_file("vch_golden_yellow_rgb"));  // 1 118 negative entries: raw values kept
  GridSpec grid;
  grid.theta_i = {{0.2, 1.0}, {1.2, 0.5}};
  grid.theta_o = regular_nodes(0.0, 1.6, 0.05);  // the last nodes are below the horizon
  grid.phi = regular_nodes(0.0, 2 * kPi - 0.02, 0.02);
  grid.cos_i_factor = true;
  for (size_t i = 0; i < grid.theta_i.size(); ++i) {
    const MetricChunk ch = build_chunk(grid, i, b);
    const Vec3d wi(std::sin(grid.theta_i[i].angle), 0.0, std::cos(grid.theta_i[i].angle));
    size_t k = 0, negative = 0;
    for (const AxisNode& to : grid.theta_o)
      for (const AxisNode& ph : grid.phi) {
        const Vec3d wo(std::sin(to.angle) * std::cos(ph.angle), std::sin(to.angle) * std::sin(ph.angle), std::cos(to.angle));
        const auto v = b.eval(wi, wo);
        if (!v) continue;
        ASSERT_LT(k, ch.size());
        EXPECT_EQ(ch.wo_x[k], wo.x());
        EXPECT_EQ(ch.wo_y[k], wo.y());
        EXPECT_EQ(ch.wo_z[k], wo.z());
        EXPECT_EQ(ch.factor[k], wi.z());
        EXPECT_EQ(ch.sqrt_weight[k], std::sqrt(grid.theta_i[i].weight * to.weight * ph.weight));
        for (int c = 0; c < 3; ++c) {
          ASSERT_EQ(ch.measured[size_t(c)][k], (*v)[c]) << k;
          negative += (*v)[c] < 0;
        }
        ++k;
      }
    EXPECT_EQ(k, ch.size());
    EXPECT_GT(k, 10000u);
    RecordProperty("negative_" + std::to_string(i), int(negative));
  }
}

// Every metric of one fit on real RGL data, against the values of the direct evaluation (`brdfkit
// error --params` with Smith G1 from smith_g1): a shortcut in the look-ups, the domains or their
// sharing fails here. The batch loops' G1 rows (shadowing/smith_g1_row.h) move these values by at
// most 1.2e-9 relative (satin low-e1), hence 5e-9. hp-rmse on its grid coarsened 4× (9 M look-ups
// in full).
TEST(RglSpeedpath, MetricValuesPinned) {
  BRDFKIT_REQUIRE_DATA("rgl");
  const Model& model = model_by_name("cook-torrance-beckmann");
  const ParamValues values = ibiza_fit(model);
  struct Pinned {
    const char* file;
    const char* metric;
    int coarsen;
    double value;
  };
  const Pinned pinned[] = {
      {"cc_ibiza_sunset_rgb", "ngan", 1, 0.2821887922884975},
      {"cc_ibiza_sunset_rgb", "bagher", 1, 4.707426140580478},
      {"cc_ibiza_sunset_rgb", "low-e1", 1, 0.31923810714591005},
      {"cc_ibiza_sunset_rgb", "low-e2", 1, 0.06343500742355783},
      {"cc_ibiza_sunset_rgb", "hp-rmse", 4, 0.2948794627082619},
      {"satin_rosaline_rgb", "ngan", 1, 0.21108375023833906},
      {"satin_rosaline_rgb", "bagher", 1, 2.140715139201462},
      {"satin_rosaline_rgb", "low-e1", 1, 1.0889351941631924},
      {"satin_rosaline_rgb", "low-e2", 1, 0.36434677949350897},
      {"satin_rosaline_rgb", "hp-rmse", 4, 0.5971097569768368},
  };
  std::map<std::string, std::unique_ptr<RglBrdf>> data;
  for (const Pinned& p : pinned) {
    SCOPED_TRACE(std::string(p.file) + " " + p.metric);
    auto& d = data[p.file];
    if (!d) d = std::make_unique<RglBrdf>(rgl_file(p.file));
    const double v = make_metric(p.metric, *d, MetricOptions{p.coarsen}).value(model, values);
    EXPECT_NEAR(v, p.value, 5e-9 * p.value);
  }
}

// A MetricStore builds each (metric, options) domain once and hands out that one object; its
// values equal a fresh build's, and so does a metric that takes its albedo norm from the store.
// Concurrent first requests of one key wait for a single build.
TEST(RglSpeedpath, StoreSharesDomainsAndTheirValuesEqualFreshBuilds) {
  BRDFKIT_REQUIRE_DATA("rgl");
  const RglBrdf b(rgl_file("satin_rosaline_rgb"));
  const Model& model = model_by_name("cook-torrance-beckmann");
  const ParamValues values = ibiza_fit(model);
  const MetricOptions coarse{3};
  const double ngan = make_metric("ngan", b, coarse).value(model, values);
  const double bagher = make_metric("bagher", b, coarse).value(model, values);
  MetricStore store(b);
  std::vector<std::shared_ptr<const Metric>> got(4);
  {
    std::vector<std::thread> threads;
    for (size_t t = 0; t < got.size(); ++t) threads.emplace_back([&, t] { got[t] = store.metric("ngan", coarse); });
    for (auto& t : threads) t.join();
  }
  for (const auto& m : got) EXPECT_EQ(m, got[0]);
  EXPECT_EQ(store.metric("ngan", coarse), got[0]);
  EXPECT_NE(store.metric("ngan", MetricOptions{4}), got[0]);  // other options: another domain
  EXPECT_EQ(got[0]->value(model, values), ngan);
  EXPECT_EQ(store.metric("bagher", coarse)->value(model, values), bagher);  // albedo norm from the store
  EXPECT_EQ(got[0]->sample_count(), make_metric("ngan", b, coarse).sample_count());
  EXPECT_THROW(store.metric("no-such-metric", coarse), InputError);
  EXPECT_THROW(store.metric("no-such-metric", coarse), InputError);  // the error is kept, not a crash
}
