// The procedures as presets (DESIGN.md §8): ids, their metrics, errors, the shared / per-channel
// shape option, and that `ngan` / `low-e*` are exactly fit_model under that metric.
#include <gtest/gtest.h>

#include <string>

#include "brdfkit/core/error.h"
#include "brdfkit/fit/procedure/per_channel_shape.h"
#include "brdfkit/fit/procedure/retabled_model.h"
#include "brdfkit/fit/procedure/procedure.h"
#include "support/fit_test_util.h"

namespace brdfkit::fit {
namespace {

using test::make_values;

double param(const Model& m, const ParamValues& v, const char* name, int c = 0) {
  return v.values[size_t(c)][size_t(find_param(m.params(), name))];
}

TEST(Procedures, IdsInStableOrderWithTheirMetrics) {
  const auto ids = procedure_registry().names();
  ASSERT_EQ(ids.size(), 6u);
  const char* want[] = {"ngan", "bagher", "low-e1", "low-e2", "hp-2step", "hp-1step"};
  for (size_t i = 0; i < ids.size(); ++i) EXPECT_EQ(ids[i], want[i]);
  auto metric_of = [](const char* id) { return fitting_metric(FitSettings{.procedure = id}); };
  EXPECT_EQ(metric_of("ngan"), "ngan");
  EXPECT_EQ(metric_of("bagher"), "bagher");
  EXPECT_EQ(metric_of("low-e1"), "low-e1");
  EXPECT_EQ(metric_of("low-e2"), "low-e2");
  EXPECT_EQ(metric_of("hp-2step"), "hp-rmse");
  EXPECT_EQ(metric_of("hp-1step"), "hp-rmse");
  EXPECT_EQ(fitting_metric(FitSettings{.procedure = "hp-2step", .metric = "low-e2"}), "low-e2");
  EXPECT_EQ(fitting_metric(FitSettings{}), "ngan");
}

TEST(Procedures, UnknownIdAndBadOptionsAreInputErrorsNamingThem) {
  const Model& m = model_by_name("lambert");
  const test::AnalyticMeasured data(m, ParamValues::defaults(m.params()));
  try {
    run_procedure(m, data, FitSettings{.procedure = "levenberg"});
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("procedure 'levenberg'"), std::string::npos) << what;
    EXPECT_EQ(what.rfind("procedure: ", 0), 0u) << what;  // a SettingError names the setting first
    EXPECT_NE(what.find("ngan, bagher, low-e1, low-e2, hp-2step, hp-1step"), std::string::npos) << what;
  }
  EXPECT_THROW(fitting_metric(FitSettings{.procedure = "nope"}), SettingError);
  FitSettings bad;
  bad.metric = "l2";
  EXPECT_THROW(run_procedure(m, data, test::with_procedure(bad, "ngan")), InputError);
  bad = {};
  bad.coarsen = 0;
  EXPECT_THROW(run_procedure(m, data, test::with_procedure(bad, "ngan")), InputError);
  // The bagher procedure needs the Bagher Fresnel term's F0, F1 (seed 000 Eq. 11).
  EXPECT_THROW(run_procedure(model_by_name("cook-torrance-beckmann"), data, FitSettings{.procedure = "bagher"}), InputError);
}

// `ngan` and `low-e*` are presets: the same numbers as fit_model under that metric.
TEST(Procedures, NganAndLowAreFitModelUnderTheirMetric) {
  const Model& m = model_by_name("cook-torrance-beckmann");
  const ParamValues want = make_values(m, {{"kd", Rgb(0.1, 0.2, 0.3)}, {"ks", Rgb(0.8, 0.6, 0.5)}, {"alpha", Rgb::Constant(0.2)}});
  const test::AnalyticMeasured data(m, want);
  for (const char* id : {"ngan", "low-e1", "low-e2"}) {
    SCOPED_TRACE(id);
    FitSettings opt;
    opt.coarsen = 4;
    int messages = 0;
    opt.procedure = id;
    const ProcedureResult r = run_procedure(m, data, opt, [&](std::string_view) { ++messages; });
    const FitResult direct = fit_model(m, make_metric(id, data, {4}), {});
    EXPECT_EQ(r.metric, id);
    EXPECT_EQ(r.fit.values.values, direct.values.values);
    EXPECT_EQ(r.fit.metric_value, direct.metric_value);
    EXPECT_NEAR(param(m, r.fit.values, "alpha"), 0.2, 2e-4);
    EXPECT_FALSE(r.steps.empty());
    EXPECT_GE(messages, 1);
  }
  // Another metric replaces the procedure's own.
  FitSettings opt;
  opt.coarsen = 4;
  opt.metric = "bagher";
  const ProcedureResult r = run_procedure(m, data, test::with_procedure(opt, "ngan"));
  EXPECT_EQ(r.metric, "bagher");
  EXPECT_EQ(r.fit.metric_value, fit_model(m, make_metric("bagher", data, {4}), {}).metric_value);
}

// One lobe shape per channel (seed 000 §5.1) through per_channel_shape_table: a material
// whose channels have different roughness is recovered channel by channel; the shared shape
// cannot do that and ends between them with a larger error.
TEST(Procedures, PerChannelShapeRecoversADifferentShapePerChannel) {
  const Model& m = model_by_name("cook-torrance-beckmann");
  const int ia = find_param(m.params(), "alpha");
  ParamValues want = make_values(m, {{"kd", Rgb(0.1, 0.2, 0.3)}, {"ks", Rgb(0.8, 0.6, 0.5)}});
  const double alpha[3] = {0.1, 0.2, 0.35};
  for (int c = 0; c < 3; ++c) want.values[size_t(c)][size_t(ia)] = alpha[c];
  const test::AnalyticMeasured data(m, want);

  const RetabledModel wrapped(m, per_channel_shape_table(m));
  EXPECT_EQ(wrapped.name(), m.name());
  ASSERT_EQ(wrapped.params().size(), m.params().size());
  for (const ParamSpec& s : wrapped.params()) EXPECT_EQ(s.scope, Scope::PerChannel) << s.name;
  EXPECT_EQ(m.params()[size_t(ia)].scope, Scope::Shared);  // the wrapped model is untouched

  FitSettings opt;
  opt.coarsen = 4;
  opt.per_channel_shape = true;
  const ProcedureResult per = run_procedure(m, data, test::with_procedure(opt, "ngan"));
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(param(m, per.fit.values, "alpha", c), alpha[c], 1e-5 * alpha[c]) << c;
    EXPECT_NEAR(param(m, per.fit.values, "ks", c), param(m, want, "ks", c), 1e-4) << c;
    EXPECT_NEAR(param(m, per.fit.values, "kd", c), param(m, want, "kd", c), 1e-5) << c;
  }
  EXPECT_LT(per.fit.metric_value, 1e-7);
  opt.per_channel_shape = false;
  const ProcedureResult shared = run_procedure(m, data, test::with_procedure(opt, "ngan"));
  const double a = param(m, shared.fit.values, "alpha");
  for (int c = 1; c < 3; ++c) EXPECT_EQ(param(m, shared.fit.values, "alpha", c), a);
  EXPECT_GT(a, alpha[0]);
  EXPECT_LT(a, alpha[2]);
  EXPECT_GT(shared.fit.metric_value, 100 * per.fit.metric_value);
  std::printf("per-channel alpha %.6g %.6g %.6g (ngan %.3g); shared alpha %.6g (ngan %.3g)\n",
              param(m, per.fit.values, "alpha", 0), param(m, per.fit.values, "alpha", 1),
              param(m, per.fit.values, "alpha", 2), per.fit.metric_value, a, shared.fit.metric_value);
}

// hp-1step (seed 004 §5.8): every parameter at once from ≥ 10 seeded restarts on the low-e1
// grid (the integrand of Eq. 29), reported under hp-rmse.
TEST(Procedures, HpOneStepFitsOnTheEq29IntegrandAndReportsHpRmse) {
  const Model& m = model_by_name("cook-torrance-ggx");
  const ParamValues want = make_values(
      m, {{"kd", Rgb(0.1, 0.2, 0.3)}, {"ks", Rgb(0.8, 0.6, 0.5)}, {"alpha", Rgb::Constant(0.25)}, {"F0", Rgb(0.05, 0.04, 0.08)}});
  const test::AnalyticMeasured data(m, want);
  FitSettings opt;
  opt.coarsen = 4;
  const ProcedureResult r = run_procedure(m, data, test::with_procedure(opt, "hp-1step"));
  EXPECT_EQ(r.metric, "hp-rmse");
  EXPECT_NEAR(param(m, r.fit.values, "alpha"), 0.25, 1e-4);
  EXPECT_LT(r.fit.metric_value, 1e-5);
  EXPECT_EQ(r.fit.metric_value, make_metric("hp-rmse", data, {4}).value(m, r.fit.values));
  // Ten restarts, deterministic.
  const ProcedureResult again = run_procedure(m, data, test::with_procedure(opt, "hp-1step"));
  EXPECT_EQ(again.fit.values.values, r.fit.values.values);
}

}  // namespace
}  // namespace brdfkit::fit
