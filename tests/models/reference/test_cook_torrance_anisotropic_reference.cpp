// cook-torrance-ggx-aniso and cook-torrance-beckmann-aniso against ρ = kd/π + ks F D G /
// (4 cosθi cosθo) (seed 004 Eq. 1) written here in the angle form of pbrt: D from tan²θh and the
// azimuth of h measured from the lobe's tangent (φh − φt), Λ as the isotropic closed form at
// α(φ) = sqrt(cos²(φ − φt) αx² + sin²(φ − φt) αy²) (pbrt-v4 src/pbrt/util/scattering.h
// TrowbridgeReitzDistribution; pbrt-v3 src/core/microfacet.cpp BeckmannDistribution). brdfkit
// writes both in the directions' components after a rotation into the lobe's frame.
#include <gtest/gtest.h>

#include <cmath>

#include "brdfkit/models/model.h"
#include "reference_fresnel.h"
#include "reference_pairs.h"
#include "reference_smith.h"

namespace brdfkit::test::ref {
namespace {

struct Lobe {
  bool ggx;
  double ax, ay, phi_t;
  double azimuth_alpha(const Vec3d& w) const {
    const double p = std::atan2(w.y(), w.x()) - phi_t;
    return std::sqrt(std::pow(std::cos(p) * ax, 2) + std::pow(std::sin(p) * ay, 2));
  }
  double D(const Vec3d& h) const {
    const double c2 = h.z() * h.z(), tan2 = (1 - c2) / c2, p = std::atan2(h.y(), h.x()) - phi_t;
    const double e = tan2 * (std::pow(std::cos(p) / ax, 2) + std::pow(std::sin(p) / ay, 2));
    return ggx ? 1 / (kPi * ax * ay * c2 * c2 * (1 + e) * (1 + e)) : std::exp(-e) / (kPi * ax * ay * c2 * c2);
  }
  double Lambda(const Vec3d& w) const {
    return ggx ? ggx_lambda(azimuth_alpha(w), w.z()) : beckmann_lambda(azimuth_alpha(w), w.z());
  }
};

void check(const Lobe& lobe) {
  const Model& m = model_by_name(lobe.ggx ? "cook-torrance-ggx-aniso" : "cook-torrance-beckmann-aniso");
  const ParamValues v = values_of(m, {{"kd", 0.15, 0},
                                      {"kd", 0.05, 1},
                                      {"kd", 0.0, 2},
                                      {"ks", 0.9, 0},
                                      {"ks", 0.6, 1},
                                      {"ks", 1.2, 2},
                                      {"F0", 0.04, 0},
                                      {"F0", 0.5, 1},
                                      {"F0", 0.95, 2},
                                      {"alpha_x", lobe.ax},
                                      {"alpha_y", lobe.ay},
                                      {"phi_t", lobe.phi_t}});
  auto reference = [&m, v, lobe](double s) -> Reference {
    return [&m, v, lobe, s](int c, const Vec3d& wi, const Vec3d& wo) {
      const Vec3d h = half_vector(wi, wo);
      const double g = 1 / ((1 + lobe.Lambda(wi)) * (1 + lobe.Lambda(wo)));
      const double spec = schlick(param(m, v, "F0", c), wi.dot(h)) * lobe.D(h) * g / (4 * wi.z() * wo.z());
      return param(m, v, "kd", c) / kPi + s * param(m, v, "ks", c) * spec;
    };
  };
  const std::string label = std::to_string(lobe.ax) + " " + std::to_string(lobe.ay) + " " + std::to_string(lobe.phi_t);
  expect_matches_reference(m, v, reference(1), 1e-10, label);
  expect_detects_five_percent(m, v, reference(1.05), 1e-10, label);
}

TEST(CookTorranceAnisotropicReference, GgxAndBeckmannAtTurnedTangents) {
  for (bool ggx : {true, false}) {
    check({ggx, 0.1, 0.4, 0.0});
    check({ggx, 0.35, 0.08, 0.7});
    check({ggx, 0.2, 0.6, -1.2});
    check({ggx, 0.3, 0.3, 2.5});  // isotropic: the angle is irrelevant
  }
}

}  // namespace
}  // namespace brdfkit::test::ref
