// Sums of models ("a+b+…", models/lobe_sum.h; seeds 002 §4.2, 003 Eq. 34) against the sum of the
// components' formulas written in this folder (reference_lobes.h, reference_ndf.h,
// reference_smith.h): ONE diffuse term kd/π (the first component's kd; later ones held at 0) plus
// every component's lobe with its `<j>.` parameters. Closed-form components: bound 1e-10.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "brdfkit/models/model.h"
#include "reference_fresnel.h"
#include "reference_lobes.h"
#include "reference_ndf.h"
#include "reference_pairs.h"
#include "reference_smith.h"

namespace brdfkit::test::ref {
namespace {

// ks F D G1 G1/(4 cosθi cosθo) with Schlick F and the closed-form Smith Λ of Beckmann or GGX.
double microfacet_lobe(bool ggx, double alpha, double ks, double f0, const Vec3d& wi, const Vec3d& wo) {
  const RefNdf d = ggx ? ref_ggx(alpha) : ref_beckmann(alpha);
  auto lambda = [&](double c) { return ggx ? ggx_lambda(alpha, c) : beckmann_lambda(alpha, c); };
  const Vec3d h = half_vector(wi, wo);
  return ks * schlick(f0, wi.dot(h)) * d.D(h.z()) / ((1 + lambda(wi.z())) * (1 + lambda(wo.z())) * 4 * wi.z() * wo.z());
}

TEST(LobeSumReference, LambertWardBlinnPhong) {
  const Model& m = model_by_name("lambert+ward+blinn-phong");
  const ParamValues v = values_of(m, {{"kd", 0.3, 0}, {"kd", 0.1, 1}, {"kd", 0.0, 2}, {"2.ks", 0.2, 0}, {"2.ks", 0.5, 1},
                                      {"2.ks", 0.05, 2}, {"2.alpha", 0.15}, {"3.ks", 0.4, 0}, {"3.ks", 0.1, 1},
                                      {"3.ks", 0.7, 2}, {"3.N", 150}});
  auto reference = [&m, v](double s) -> Reference {
    return [&m, v, s](int c, const Vec3d& wi, const Vec3d& wo) {
      const double a = param(m, v, "2.alpha", c);
      return param(m, v, "kd", c) / kPi +
             s * (param(m, v, "2.ks", c) * ward_aniso_lobe(wi, wo, a, a, false) +
                  param(m, v, "3.ks", c) * blinn_phong_lobe(wi, wo, param(m, v, "3.N", c)));
    };
  };
  expect_matches_reference(m, v, reference(1), 1e-10, "kd + ward + blinn-phong");
  expect_detects_five_percent(m, v, reference(1.05), 1e-10, "kd + ward + blinn-phong");
}

TEST(LobeSumReference, TwoMicrofacetLobes) {
  const Model& m = model_by_name("cook-torrance-ggx+cook-torrance-beckmann");
  const ParamValues v = values_of(m, {{"kd", 0.1, 0}, {"kd", 0.0, 2}, {"1.ks", 0.8}, {"1.alpha", 0.3}, {"1.F0", 0.04, 0},
                                      {"1.F0", 0.5, 1}, {"1.F0", 0.9, 2}, {"2.ks", 0.5, 0}, {"2.ks", 1.0, 1},
                                      {"2.ks", 0.2, 2}, {"2.alpha", 0.06}, {"2.F0", 0.3}});
  auto reference = [&m, v](double s) -> Reference {
    return [&m, v, s](int c, const Vec3d& wi, const Vec3d& wo) {
      return param(m, v, "kd", c) / kPi +
             s * (microfacet_lobe(true, param(m, v, "1.alpha", c), param(m, v, "1.ks", c), param(m, v, "1.F0", c), wi, wo) +
                  microfacet_lobe(false, param(m, v, "2.alpha", c), param(m, v, "2.ks", c), param(m, v, "2.F0", c), wi, wo));
    };
  };
  expect_matches_reference(m, v, reference(1), 1e-10, "ggx + beckmann");
  expect_detects_five_percent(m, v, reference(1.05), 1e-10, "ggx + beckmann");
}

// The same model twice: the second's kd is held at 0, each lobe keeps its own parameters.
TEST(LobeSumReference, RepeatedLafortune) {
  const Model& m = model_by_name("lafortune+lafortune");
  const ParamValues v = values_of(m, {{"kd", 0.2}, {"1.ks", 0.5}, {"1.Cxy", -1.0}, {"1.Cz", 0.9}, {"1.N", 40},
                                      {"2.ks", 0.3, 0}, {"2.ks", 0.6, 1}, {"2.ks", 0.1, 2}, {"2.Cxy", 0.4},
                                      {"2.Cz", 1.0}, {"2.N", 2.5}});
  auto reference = [&m, v](double s) -> Reference {
    return [&m, v, s](int c, const Vec3d& wi, const Vec3d& wo) {
      double sum = param(m, v, "kd", c) / kPi;
      for (const std::string j : {"1.", "2."})
        sum += s * param(m, v, j + "ks", c) *
               lafortune_lobe(wi, wo, param(m, v, j + "Cxy", c), param(m, v, j + "Cz", c), param(m, v, j + "N", c));
      return sum;
    };
  };
  expect_matches_reference(m, v, reference(1), 1e-10, "two lafortune lobes");
  expect_detects_five_percent(m, v, reference(1.05), 1e-10, "two lafortune lobes");
}

}  // namespace
}  // namespace brdfkit::test::ref
