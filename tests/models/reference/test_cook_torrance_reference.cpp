// Every Cook-Torrance model of the catalogue against ρ = kd/π + ks F(θd) D(θh) G(wi, wo) /
// (4 cosθi cosθo) (seed 004 Eq. 1, DESIGN.md §6) written in this file with the distributions of
// reference_ndf.h (DESIGN.md §3), Smith's Λ of reference_smith.h (closed forms for Beckmann and
// GGX, quadrature otherwise; DESIGN.md §4), Schlick's, Bagher's and the dielectric Fresnel terms
// (DESIGN.md §5) and the V-groove G — none of it brdfkit's code.
//
// Bounds: 1e-10 relative where every term has a closed form (measured ≤ 1e-14). Where brdfkit
// interpolates Λ from its table (shadowing/smith_table.h), 1e-5: the worst difference measured
// over these pairs is 4.5e-6 (Gaussian m = 0.6, at θ = 88°), ~2e-6 for the others; the reference
// quadrature itself agrees with the closed forms to 1e-11.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "brdfkit/models/microfacet_model.h"
#include "brdfkit/models/model.h"
#include "reference_fresnel.h"
#include "reference_ndf.h"
#include "reference_pairs.h"
#include "reference_smith.h"

namespace brdfkit::test::ref {
namespace {

struct NdfCase {
  RefNdf ndf;
  double rel_tol;  // bound on |model − reference| / reference
};

// Two or three shapes per distribution: sharp and wide, and the special branches (GTR γ = 1,
// SGD with 1 − p < 0, the exponential power's p > 1).
std::vector<NdfCase> ndf_cases() {
  return {
      {ref_beckmann(0.15), 1e-10},        {ref_beckmann(0.5), 1e-10},
      {ref_ggx(0.1), 1e-10},              {ref_ggx(0.6), 1e-10},
      {ref_blinn_phong(20), 1e-5},        {ref_blinn_phong(300), 1e-5},
      {ref_gaussian(0.1), 1e-5},          {ref_gaussian(0.6), 1e-5},
      {ref_gtr(0.2, 1.5), 1e-5},          {ref_gtr(0.3, 1.0), 1e-5},         {ref_gtr(0.1, 3.0), 1e-5},
      {ref_exponential(0.1), 1e-5},       {ref_exponential(0.4), 1e-5},
      {ref_sgd(0.05, 0.6), 1e-5},         {ref_sgd(0.2, 1.3), 1e-5},
      {ref_exponential_power(0.1, 0.6), 1e-5}, {ref_exponential_power(0.3, 1.7), 1e-5},
      {ref_schlick_rational(0.2), 1e-5},  {ref_schlick_rational(0.6), 1e-5},
      {ref_sawicki_rational(30), 1e-5},   {ref_sawicki_rational(500), 1e-5},
  };
}

std::string label_of(const RefNdf& d) {
  std::string s;
  for (size_t i = 0; i < d.params.size(); ++i) s += (i ? " " : "") + d.param_names[i] + "=" + std::to_string(d.params[i]);
  return s;
}

double lambda_of(const RefNdf& d, double cos_theta) {
  if (d.name == "beckmann") return beckmann_lambda(d.params[0], cos_theta);
  if (d.name == "ggx") return ggx_lambda(d.params[0], cos_theta);
  return smith_lambda_numeric(d, cos_theta);
}

// Colours differ per channel so a channel mix-up shows; channel 2 has no diffuse term, so the
// lobe's normalization is all there is.
const std::vector<Setting> kColours = {{"kd", 0.15, 0}, {"kd", 0.05, 1}, {"kd", 0.0, 2},
                                       {"ks", 0.9, 0},  {"ks", 0.6, 1},  {"ks", 1.2, 2}};

// kd/π + s · ks F D G/(4 cosθi cosθo) with the given Fresnel and masking terms (s = 1 is the
// model; s = 1.05 is the sensitivity check).
template <class F, class G>
Reference microfacet_reference(const Model& m, const ParamValues& v, const RefNdf& d, F fresnel, G masking, double s = 1) {
  return [&m, v, d, fresnel, masking, s](int c, const Vec3d& wi, const Vec3d& wo) {
    const Vec3d h = half_vector(wi, wo);
    const double spec = fresnel(c, wi.dot(h)) * d.D(h.z()) * masking(wi, wo) / (4 * wi.z() * wo.z());
    return param(m, v, "kd", c) / kPi + s * param(m, v, "ks", c) * spec;
  };
}
auto smith_uncorrelated(const RefNdf& d) {
  return [d](const Vec3d& wi, const Vec3d& wo) { return 1 / ((1 + lambda_of(d, wi.z())) * (1 + lambda_of(d, wo.z()))); };
}

// ∫ D cosθ dω = 2π ∫₀^{π/2} D(θ) cosθ sinθ dθ, adaptive Gauss-Kronrod (the support edge of a
// compact distribution as the upper limit), at most 2¹⁰ panels.
template <class Dfun> double projected_area(Dfun D, double theta_max = kPi / 2) {
  return 2 * kPi * boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
                       [&](double t) { return D(std::cos(t)) * std::cos(t) * std::sin(t); }, 0.0, theta_max, 10, 1e-12);
}
double theta_max_of(const RefNdf& d) { return std::isfinite(d.x_max) ? std::atan(std::sqrt(d.x_max)) : kPi / 2; }

TEST(CookTorranceReference, ReferenceDistributionsAreNormalized) {
  for (const NdfCase& k : ndf_cases())
    EXPECT_NEAR(projected_area([&](double c) { return k.ndf.D(c); }, theta_max_of(k.ndf)), 1.0, 1e-9)
        << k.ndf.name << " " << label_of(k.ndf);
}

TEST(CookTorranceReference, ReferenceSmithQuadratureMatchesClosedForms) {
  for (double a : {0.05, 0.3, 1.2})
    for (double deg = 5; deg < 89.9; deg += 7) {
      const double c = std::cos(deg * kPi / 180);
      EXPECT_NEAR(smith_g1_numeric(ref_beckmann(a), c), 1 / (1 + beckmann_lambda(a, c)), 1e-11) << a << " " << deg;
      EXPECT_NEAR(smith_g1_numeric(ref_ggx(a), c), 1 / (1 + ggx_lambda(a, c)), 1e-11) << a << " " << deg;
    }
}

TEST(CookTorranceReference, EveryDistributionWithSchlickAndSmith) {
  const std::vector<Setting> fresnel = {{"F0", 0.04, 0}, {"F0", 0.5, 1}, {"F0", 0.95, 2}};
  for (const NdfCase& k : ndf_cases()) {
    const Model& m = model_by_name("cook-torrance-" + k.ndf.name);
    std::vector<Setting> s = kColours;
    s.insert(s.end(), fresnel.begin(), fresnel.end());
    for (size_t i = 0; i < k.ndf.params.size(); ++i) s.push_back({k.ndf.param_names[i], k.ndf.params[i]});
    const ParamValues v = values_of(m, s);
    auto f = [&m, v](int c, double cd) { return schlick(param(m, v, "F0", c), cd); };
    expect_matches_reference(m, v, microfacet_reference(m, v, k.ndf, f, smith_uncorrelated(k.ndf)), k.rel_tol,
                             label_of(k.ndf));
    expect_detects_five_percent(m, v, microfacet_reference(m, v, k.ndf, f, smith_uncorrelated(k.ndf), 1.05), k.rel_tol,
                                label_of(k.ndf));
  }
}

// Ngan et al. 2005's form (seed 002 §4): Beckmann, Schlick, V-groove.
TEST(CookTorranceReference, NganBeckmannSchlickVGroove) {
  const Model& m = model_by_name("cook-torrance");
  for (double a : {0.08, 0.35}) {
    std::vector<Setting> s = kColours;
    s.insert(s.end(), {{"alpha", a}, {"F0", 0.02, 0}, {"F0", 0.3, 1}, {"F0", 0.8, 2}});
    const ParamValues v = values_of(m, s);
    const RefNdf d = ref_beckmann(a);
    auto f = [&m, v](int c, double cd) { return schlick(param(m, v, "F0", c), cd); };
    expect_matches_reference(m, v, microfacet_reference(m, v, d, f, v_groove), 1e-10, "alpha=" + std::to_string(a));
    expect_detects_five_percent(m, v, microfacet_reference(m, v, d, f, v_groove, 1.05), 1e-10, "alpha");
  }
}

// Löw 2012's published Cook-Torrance (published_fits.h): Beckmann, dielectric F(η), V-groove.
TEST(CookTorranceReference, Low2012BeckmannDielectricVGroove) {
  const Model& m = model_by_name("cook-torrance-low2012");
  for (double a : {0.05, 0.4}) {
    std::vector<Setting> s = kColours;
    s.insert(s.end(), {{"alpha", a}, {"eta", 1.3, 0}, {"eta", 1.8, 1}, {"eta", 4.0, 2}});
    const ParamValues v = values_of(m, s);
    auto f = [&m, v](int c, double cd) { return fresnel_dielectric(cd, param(m, v, "eta", c)); };
    expect_matches_reference(m, v, microfacet_reference(m, v, ref_beckmann(a), f, v_groove), 1e-10,
                             "alpha=" + std::to_string(a));
    expect_detects_five_percent(m, v, microfacet_reference(m, v, ref_beckmann(a), f, v_groove, 1.05), 1e-10, "alpha");
  }
}

// Bagher 2012's published model (published_fits.h): SGD D, F0 + (1 − F0)(1 − cosθd)⁵ − F1 cosθd
// (seed 000 Eq. 11), uncorrelated Smith G from the SGD's own Λ.
TEST(CookTorranceReference, Bagher2012SgdWithLinearFresnelTerm) {
  const Model& m = model_by_name("cook-torrance-sgd-bagher2012");
  for (auto [a, p] : {std::pair{0.03, 0.5}, std::pair{0.15, 1.2}}) {
    std::vector<Setting> s = kColours;
    s.insert(s.end(), {{"alpha", a}, {"p", p}, {"F0", 0.05, 0}, {"F0", 0.4, 1}, {"F0", 0.9, 2},
                       {"F1", 0.02, 0}, {"F1", -0.1, 1}, {"F1", 0.3, 2}});
    const ParamValues v = values_of(m, s);
    auto f = [&m, v](int c, double cd) {
      return schlick(param(m, v, "F0", c), cd) - param(m, v, "F1", c) * cd;  // seed 000 Eq. 11
    };
    const RefNdf d = ref_sgd(a, p);
    const std::string label = "alpha=" + std::to_string(a) + " p=" + std::to_string(p);
    expect_matches_reference(m, v, microfacet_reference(m, v, d, f, smith_uncorrelated(d)), 1e-5, label);
    expect_detects_five_percent(m, v, microfacet_reference(m, v, d, f, smith_uncorrelated(d), 1.05), 1e-5, label);
  }
}

// The D every registered microfacet model evaluates (the view `brdfkit check` integrates) has
// unit projected area at its defaults: a missing 1/π or a wrong constant is off by far more.
TEST(CookTorranceReference, RegisteredDistributionsHaveUnitProjectedArea) {
  int checked = 0;
  for (const Model* m : all_models()) {
    const auto* view = dynamic_cast<const MicrofacetDistributionView*>(m);
    if (!view) continue;
    const ParamValues v = ParamValues::defaults(m->params());
    const double area = projected_area([&](double c) { return view->ndf(v.channel(0), c); });
    EXPECT_NEAR(area, 1.0, 1e-7) << m->name();
    ++checked;
  }
  EXPECT_GE(checked, 13);  // the 11 cook-torrance-* models, low2012, bagher2012 (and holzschuch-pacanowski)
}

}  // namespace
}  // namespace brdfkit::test::ref
