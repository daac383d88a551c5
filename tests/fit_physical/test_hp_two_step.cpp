// hp-2step (seed 004 §5.8, DESIGN.md §8) on the material of tests/procedures: why step 2 ended
// with σ at its bound. Diagnosis (numbers printed; being written).
#include <gtest/gtest.h>

#include <cstdio>

#include "brdfkit/analysis/diffraction_map.h"
#include "brdfkit/core/half_diff.h"
#include "brdfkit/fit/metric.h"
#include "brdfkit/fit/procedure.h"
#include "fit/fit_test_util.h"

namespace brdfkit::fit {
namespace {

ParamValues material(const Model& m) {
  return test::make_values(m, {{"kd", Rgb(0.05, 0.04, 0.03)},
                               {"ks", Rgb(0.6, 0.5, 0.4)},
                               {"kw", Rgb(0.02, 0.01, 0.005)},
                               {"sigma", Rgb::Constant(0.05)},
                               {"p", Rgb::Constant(0.6)},
                               {"a", Rgb::Constant(1.0)},
                               {"F0", Rgb(0.05, 0.05, 0.05)}});
}

void print(const Model& m, const ParamValues& v) {
  for (size_t i = 0; i < m.params().size(); ++i)
    std::printf("   %-7s %.6g %.6g %.6g\n", m.params()[i].name.c_str(), v.values[0][i], v.values[1][i], v.values[2][i]);
}

TEST(HpTwoStep, Diagnosis) {
  const Model& m = model_by_name("holzschuch-pacanowski");
  const ParamValues want = material(m);
  const test::AnalyticMeasured data(m, want);
  // Which cells the classification calls diffraction-dominated, and what dominates them.
  const analysis::DiffractionMap map = analysis::diffraction_map(data);
  ParamValues no_reflection = want, no_diffraction = want;
  for (auto& ch : no_reflection.values) ch[1] = 0.0;
  for (auto& ch : no_diffraction.values) ch[2] = 0.0;
  const Brdf full(m, want), refl_off(m, no_reflection), diff_off(m, no_diffraction);
  int all = 0, reflection_major = 0, diffuse_major = 0, diffraction_major = 0;
  for (const auto& cell : map.cells) {
    bool every = true;
    for (int c = 0; c < 3; ++c) every = every && cell.has_det[size_t(c)] && cell.diffraction[size_t(c)];
    if (!every) continue;
    ++all;
    Vec3d wi, wo;
    from_half_diff({cell.theta_h, 0.0, cell.theta_d, kPi / 2}, wi, wo);
    const double rho = full.eval(wi, wo)[1];
    const double refl = rho - refl_off.eval(wi, wo)[1], diff = rho - diff_off.eval(wi, wo)[1];
    if (refl > 0.5 * rho) ++reflection_major;
    else if (diff > 0.5 * rho) ++diffraction_major;
    else ++diffuse_major;
  }
  std::printf("cells diffraction-dominated in all channels: %d; by the truth's lobes (G, phi_d = 90 deg): "
              "reflection > 1/2 in %d, diffraction > 1/2 in %d, else (diffuse) %d\n",
              all, reflection_major, diffraction_major, diffuse_major);
  for (int coarsen : {8, 4}) {
    ProcedureOptions opt;
    opt.coarsen = coarsen;
    const ProcedureResult two = run_procedure("hp-2step", m, data, opt);
    for (const auto& s : two.steps) std::printf("coarsen %d: %s\n", coarsen, s.c_str());
    print(m, two.fit.values);
    const Metric e1 = make_metric("low-e1", data, {coarsen});
    std::printf("low-e1 at the result %.4g, at the truth %.4g\n", e1.value(m, two.fit.values), e1.value(m, want));
  }
}

}  // namespace
}  // namespace brdfkit::fit
