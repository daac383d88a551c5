// `ward`, `ward-aniso` and `ward-duer` against Ward 1992's Eq. 5a and Dür 2006's variant as
// DESIGN.md §6 writes them, transcribed here with angles (θh, φh from the half vector):
//   ward       kd/π + ks exp(−tan²θh/α²) / (4π α² sqrt(cosθi cosθo))
//   ward-aniso kd/π + ks exp(−tan²θh (cos²φh/αx² + sin²φh/αy²)) / (4π αx αy sqrt(cosθi cosθo))
//   ward-duer  kd/π + ks exp(−tan²θh/α²) / (4π α² cosθi cosθo)
// Every term is closed-form: bound 1e-10 relative.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "brdfkit/models/model.h"
#include "reference_lobes.h"
#include "reference_pairs.h"

namespace brdfkit::test::ref {
namespace {

const std::vector<Setting> kColours = {{"kd", 0.2, 0}, {"kd", 0.05, 1}, {"kd", 0.0, 2},
                                       {"ks", 0.3, 0}, {"ks", 0.8, 1},  {"ks", 0.05, 2}};

Reference ward_reference(const Model& m, const ParamValues& v, bool aniso, bool duer, double norm = kWardNorm) {
  return [&m, v, aniso, duer, norm](int c, const Vec3d& wi, const Vec3d& wo) {
    const double ax = param(m, v, aniso ? "alpha_x" : "alpha", c), ay = param(m, v, aniso ? "alpha_y" : "alpha", c);
    return param(m, v, "kd", c) / kPi + param(m, v, "ks", c) * ward_aniso_lobe(wi, wo, ax, ay, duer, norm);
  };
}

TEST(WardReference, IsotropicWard1992) {
  const Model& m = model_by_name("ward");
  for (double a : {0.05, 0.2, 0.6}) {
    std::vector<Setting> s = kColours;
    s.push_back({"alpha", a});
    const ParamValues v = values_of(m, s);
    const std::string label = "alpha=" + std::to_string(a);
    expect_matches_reference(m, v, ward_reference(m, v, false, false), 1e-10, label);
    expect_detects_five_percent(m, v, ward_reference(m, v, false, false, kWardNorm / 1.05), 1e-10, label);
  }
}

TEST(WardReference, AnisotropicWard1992) {
  const Model& m = model_by_name("ward-aniso");
  for (auto [ax, ay] : {std::pair{0.08, 0.3}, std::pair{0.5, 0.1}}) {
    std::vector<Setting> s = kColours;
    s.insert(s.end(), {{"alpha_x", ax}, {"alpha_y", ay}});
    const ParamValues v = values_of(m, s);
    const std::string label = "ax=" + std::to_string(ax) + " ay=" + std::to_string(ay);
    expect_matches_reference(m, v, ward_reference(m, v, true, false), 1e-10, label);
    expect_detects_five_percent(m, v, ward_reference(m, v, true, false, kWardNorm / 1.05), 1e-10, label);
    // The axes matter: αx and αy exchanged is another BRDF at these pairs (φh ≠ 0, π/2).
    std::vector<Setting> t = kColours;
    t.insert(t.end(), {{"alpha_x", ay}, {"alpha_y", ax}});
    EXPECT_GT(max_relative_difference(m, values_of(m, t), ward_reference(m, v, true, false)), 0.05) << label;
  }
}

TEST(WardReference, WardDuer2006) {
  const Model& m = model_by_name("ward-duer");
  for (double a : {0.05, 0.3}) {
    std::vector<Setting> s = kColours;
    s.push_back({"alpha", a});
    const ParamValues v = values_of(m, s);
    const std::string label = "alpha=" + std::to_string(a);
    expect_matches_reference(m, v, ward_reference(m, v, false, true), 1e-10, label);
    expect_detects_five_percent(m, v, ward_reference(m, v, false, true, kWardNorm / 1.05), 1e-10, label);
  }
}

// `ward-aniso` with αx = αy is `ward`, at every pair, channel and width (to rounding).
TEST(WardReference, AnisotropicEqualsIsotropicForEqualWidths) {
  const Model& iso = model_by_name("ward");
  const Model& aniso = model_by_name("ward-aniso");
  for (double a : {0.01, 0.1, 0.45, 1.0}) {
    std::vector<Setting> s = kColours, t = kColours;
    s.push_back({"alpha", a});
    t.insert(t.end(), {{"alpha_x", a}, {"alpha_y", a}});
    const ParamValues vi = values_of(iso, s), va = values_of(aniso, t);
    for (const DirectionPair& d : direction_pairs())
      for (int c = 0; c < 3; ++c) {
        const double x = iso.eval(vi.channel(c), c, d.wi(), d.wo()), y = aniso.eval(va.channel(c), c, d.wi(), d.wo());
        EXPECT_NEAR(y, x, 1e-13 * std::abs(x) + 1e-300) << "alpha " << a << " pair " << d.theta_i << "," << d.theta_o;
      }
  }
}

}  // namespace
}  // namespace brdfkit::test::ref
