// The projected objective's gradient Jᵀr is half the derivative of its cost (objective.h: cost =
// Σ r²), checked against central differences of the cost itself at a point where the fit is poor
// (large residuals): He, whose shape has shared variables (σ0, τ) and per-channel ones (η, k: the
// Fresnel ratio of Model::eval_batch_from), and GGX, whose shape is one shared roughness.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "brdfkit/core/pair_arrays.h"
#include "brdfkit/fit/engine/linear_structure.h"
#include "brdfkit/fit/engine/projected_objective.h"
#include "support/merl_cases.h"

namespace brdfkit::fit {
namespace {

struct Domain {
  PairArrays pairs;
  std::vector<double> m[3];
};

// Pairs above the horizon, measured = `truth` model's ρ with a smooth multiplicative ripple.
Domain make_domain(const Model& truth, const ParamValues& tp, size_t n) {
  Domain d;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  for (size_t k = 0; k < n; ++k) {
    const Vec3d wi = spherical_direction(std::acos(0.05 + 0.95 * u(rng)), 0.0);
    const Vec3d wo = spherical_direction(std::acos(0.05 + 0.95 * u(rng)), 2 * kPi * u(rng));
    d.pairs.push_pair(wi, wo);
    for (int c = 0; c < 3; ++c)
      d.m[c].push_back(truth.eval(tp.values[size_t(c)].data(), c, wi, wo) * (1 + 0.3 * std::sin(7.0 * wo.x() + c)));
  }
  return d;
}

// The domain as two blocks of unit weight, so the objective's partial sums are reduced across blocks.
std::vector<SampleBlock> blocks_of(const Domain& d) {
  std::vector<SampleBlock> out;
  const size_t n = d.pairs.wi_x.size(), half = n / 2;
  for (size_t a : {size_t(0), half}) {
    const size_t len = a == 0 ? half : n - half;
    SampleBlock b;
    b.n = len;
    b.d = {d.pairs.wi_x.data() + a, d.pairs.wi_y.data() + a, d.pairs.wi_z.data() + a,
           d.pairs.wo_x.data() + a, d.pairs.wo_y.data() + a, d.pairs.wo_z.data() + a};
    for (int c = 0; c < 3; ++c) b.m[c] = d.m[c].data() + a;
    b.w2.assign(len, 1.0);
    b.rw.assign(len, 1.0);
    out.push_back(std::move(b));
  }
  return out;
}

// Worst |Jᵀr − ½ ∂cost/∂x| over the variables, relative to the largest |Jᵀr|. The objective's own
// derivatives are forward differences of step 1e-6 relative (finite_difference.h): ~1e-6.
double gradient_error(const Model& model, const ParamValues& at, const Domain& d) {
  const LinearStructure s = probe_linear_structure(model, true);
  const SolverVariables vars(model.params(), solved_inside(s, true));
  FitContext ctx{model, vars, Transform::Identity, blocks_of(d), 1, at};
  ProjectedObjective obj(ctx, s.bases);
  obj.reset(true);
  std::vector<double> x(vars.size());
  vars.read(at, x.data());
  ObjectiveValue o;
  ParamValues pv;
  EXPECT_TRUE(obj.evaluate(x.data(), true, o, pv));
  double worst = 0;
  for (size_t v = 0; v < vars.size(); ++v) {
    const double h = 1e-5 * std::max(std::abs(x[v]), 1e-2);
    std::vector<double> xp = x, xm = x;
    xp[v] += h;
    xm[v] -= h;
    ObjectiveValue op, om;
    EXPECT_TRUE(obj.evaluate(xp.data(), false, op, pv));
    EXPECT_TRUE(obj.evaluate(xm.data(), false, om, pv));
    const double numeric = 0.25 * (op.cost - om.cost) / h;
    worst = std::max(worst, std::abs(o.gradient[Eigen::Index(v)] - numeric));
  }
  const double relative = worst / o.gradient.cwiseAbs().maxCoeff();
  std::printf("%s: %zu variables, worst |Jtr - cost'/2| = %.3g of the largest component\n",
              std::string(model.name()).c_str(), vars.size(), relative);
  return relative;
}

TEST(ProjectedObjective, GradientIsHalfTheCostsDerivative) {
  const Model& he = model_by_name("he");
  const ParamValues truth = test::with(he, {{"sigma0", Rgb::Constant(0.3)},
                                            {"tau", Rgb::Constant(4)},
                                            {"eta", Rgb(1.6, 1.7, 1.8)},
                                            {"k", Rgb(0.1, 0.2, 0.3)},
                                            {"kd", Rgb(0.3, 0.2, 0.1)}});
  const Domain d = make_domain(he, truth, 4000);
  const ParamValues at = test::with(he, {{"sigma0", Rgb::Constant(0.25)},
                                         {"tau", Rgb::Constant(5)},
                                         {"eta", Rgb(1.4, 2.0, 1.5)},
                                         {"k", Rgb(0.3, 0.05, 0.5)}});
  EXPECT_LT(gradient_error(he, at, d), 1e-5);
  const Model& ggx = model_by_name("cook-torrance-ggx");
  EXPECT_LT(gradient_error(ggx, test::with(ggx, {{"alpha", Rgb::Constant(0.2)}}), d), 1e-5);
}

}  // namespace
}  // namespace brdfkit::fit
