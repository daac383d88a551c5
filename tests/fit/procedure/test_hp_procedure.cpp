// Holzschuch & Pacanowski 2015 (seed 004) §5.8: hp-2step (diffuse + diffraction on the
// diffraction-dominated cells, then the reflection lobe) and hp-1step (all at once, ≥ 10
// restarts), on a material made from the model itself with a visible diffraction lobe.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/diffraction_map.h"
#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/fit/procedure/fixed_params.h"
#include "brdfkit/fit/procedure/procedure.h"
#include "support/fit_test_util.h"

namespace brdfkit::fit {
namespace {

double param(const Model& m, const ParamValues& v, const char* name, int c = 0) {
  return v.values[size_t(c)][size_t(find_param(m.params(), name))];
}

// Holding parameters fixed: the free ones form the table, evaluation and merging agree with
// the full model.
TEST(FixedParams, EvaluatesTheFullModelWithTheHeldValues) {
  const Model& m = model_by_name("cook-torrance-ggx");
  const ParamValues full = test::make_values(m, {{"kd", Rgb(0.1, 0.2, 0.3)}, {"ks", Rgb(0.7, 0.6, 0.5)},
                                                 {"alpha", Rgb::Constant(0.3)}, {"F0", Rgb(0.04, 0.05, 0.06)}});
  std::vector<bool> hold(m.params().size(), false);
  hold[size_t(find_param(m.params(), "kd"))] = true;
  hold[size_t(find_param(m.params(), "F0"))] = true;
  const FixedParams fixed(m, hold, full);
  ASSERT_EQ(fixed.params().size(), m.params().size() - 2);
  EXPECT_EQ(find_param(fixed.params(), "kd"), -1);
  const ParamValues free = fixed.free_part(full);
  EXPECT_EQ(fixed.merged(free).values, full.values);
  const Vec3d wi = spherical_direction(0.4, 0.0), wo = spherical_direction(0.6, 2.5);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(fixed.eval(free.channel(c), c, wi, wo), m.eval(full.channel(c), c, wi, wo));
}

TEST(HpProcedure, TwoStepNeedsADiffractionLobe) {
  const Model& m = model_by_name("cook-torrance-ggx");
  const test::AnalyticMeasured data(m, ParamValues::defaults(m.params()));
  try {
    run_procedure(m, data, FitSettings{.procedure = "hp-2step"});
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("kd, kw and a"), std::string::npos) << e.what();
  }
}

// Reads "R n/N, G n/N, B n/N, all three channels n" from the classification step's line.
std::array<int, 4> classified_counts(const std::string& step) {
  std::array<int, 4> n{-1, -1, -1, -1};
  const char* keys[] = {" R ", " G ", " B ", "all three channels "};
  for (int k = 0; k < 4; ++k) {
    const auto at = step.find(keys[k]);
    if (at != std::string::npos) n[size_t(k)] = std::stoi(step.substr(at + std::strlen(keys[k])));
  }
  return n;
}

// The value after "low-e1 = " in a step's line.
double step_low_e1(const std::string& step) {
  const auto at = step.find("low-e1 = ");
  return at == std::string::npos ? std::nan("") : std::stod(step.substr(at + 9));
}

TEST(HpProcedure, TwoStepOnAMaterialWithDiffraction) {
  const Model& m = model_by_name("holzschuch-pacanowski");
  const ParamValues want = test::hp_diffraction_material(m);
  const test::AnalyticMeasured data(m, want);
  // The HP model's evaluation is costly (a Γ per call): a coarse grid, and hp-1step's ten
  // restarts are left to the GGX test of test_procedures.cpp.
  FitSettings opt;
  opt.coarsen = 8;
  const ProcedureResult two = run_procedure(m, data, test::with_procedure(opt, "hp-2step"));
  const ParamValues zero_values = [&] {
    ParamValues v = want;
    for (auto& ch : v.values) ch[1] = ch[2] = ch[0] = 0.0;  // kd, ks, kw = 0: the data's own norm
    return v;
  }();
  const double zero = make_metric("hp-rmse", data, {8}).value(m, zero_values);
  for (const auto& s : two.steps) std::printf("hp-2step: %s\n", s.c_str());
  std::printf("hp-rmse: 2-step %.4g, zero model %.4g; a %.4g (true 1), kd %.4g %.4g %.4g (true 0.05 0.04 0.03), "
              "kw[r] %.4g (true 0.02), sigma %.4g (true 0.05)\n",
              two.fit.metric_value, zero, param(m, two.fit.values, "a"), param(m, two.fit.values, "kd", 0),
              param(m, two.fit.values, "kd", 1), param(m, two.fit.values, "kd", 2), param(m, two.fit.values, "kw"),
              param(m, two.fit.values, "sigma"));
  EXPECT_EQ(two.metric, "hp-rmse");
  ASSERT_EQ(two.steps.size(), 4u);

  // Step 0 classifies the cells of the diffraction map (seed 004 §4.2) at the default threshold:
  // its counts are the map's.
  EXPECT_EQ(two.steps[0].rfind("classified (θh, θd) cells with |det(∇ log ρ, ∇f)| < 0.01 ", 0), 0u) << two.steps[0];
  const DiffractionMap map = diffraction_map(data);
  int every = 0;
  for (const auto& cell : map.cells) {
    bool all = true;
    for (int c = 0; c < 3; ++c) all = all && cell.has_det[size_t(c)] && cell.diffraction[size_t(c)];
    every += all;
  }
  const auto counts = classified_counts(two.steps[0]);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(counts[size_t(c)], map.diffraction_cells[size_t(c)]) << "channel " << c;
  EXPECT_EQ(counts[3], every);

  // Step 1 (kd, kw, a on those cells, ks = 0) recovers the diffraction lobe and the diffuse term:
  // measured a 0.966, kw[r] 0.02004, kd 0.0520 0.0415 0.0310 (3-4 % high: the reflection lobe's
  // tail in the classified cells biases them; test_hp_two_step.cpp).
  EXPECT_NEAR(param(m, two.fit.values, "a"), 1.0, 0.05);
  EXPECT_NEAR(param(m, two.fit.values, "kw"), 0.02, 0.05 * 0.02);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(param(m, two.fit.values, "kd", c), want.values[size_t(c)][0], 0.05 * want.values[size_t(c)][0]) << c;
  // Step 2's number is the low-e1 of the returned values on the same grid, far below the zero
  // model's (measured 5.7e-6).
  const Metric e1 = make_metric("low-e1", data, {8});
  EXPECT_NEAR(step_low_e1(two.steps[2]), e1.value(m, two.fit.values), 1e-5 * e1.value(m, two.fit.values)) << two.steps[2];
  EXPECT_LT(e1.value(m, two.fit.values), 1e-3 * e1.value(m, zero_values));
  // The reported hp-rmse is the metric of the returned values, below the zero model's (0.452 vs
  // 0.501). Recovery of σ is not asserted here: an 8° grid cannot resolve the σ = 0.05 lobe (the
  // best fit on it has σ ≈ 0.035); test_hp_two_step.cpp recovers σ on a 4° grid.
  EXPECT_NEAR(two.fit.metric_value, make_metric("hp-rmse", data, {8}).value(m, two.fit.values), 1e-9 * zero);
  EXPECT_LT(two.fit.metric_value, 0.95 * zero);
  EXPECT_GT(param(m, two.fit.values, "sigma"), 0.02);
  EXPECT_LT(param(m, two.fit.values, "sigma"), 0.05);
}

}  // namespace
}  // namespace brdfkit::fit
