// The renderer models of the catalogue against independent transcriptions of the renderers'
// formulas (renderer_reference.h): 40 direction pairs × several parameter sets each, to 1e-6
// relative; and the usual conversion mistakes (roughness squared twice, F0 taken as an IOR, the
// wrong distribution, a gamma-encoded colour taken as linear) must fail the same comparison.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "brdfkit/core/error.h"
#include "brdfkit/models/model.h"
#include "renderer_reference.h"

namespace brdfkit {
namespace {

namespace ref = test::reference;

// 40 direction pairs, θ ≤ 85°, away from the exact mirror direction.
std::vector<std::pair<Vec3d, Vec3d>> direction_pairs() {
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::pair<Vec3d, Vec3d>> out;
  while (out.size() < 40) {
    const Vec3d l = spherical_direction(std::acos(1 - u(rng) * (1 - std::cos(85 * kPi / 180))), 2 * kPi * u(rng));
    const Vec3d v = spherical_direction(std::acos(1 - u(rng) * (1 - std::cos(85 * kPi / 180))), 2 * kPi * u(rng));
    if ((l + v).normalized().z() < 0.9999) out.emplace_back(l, v);
  }
  return out;
}

using Values = std::vector<std::pair<std::string, std::vector<double>>>;  // name → 1 or 3 values
using Reference = std::function<std::array<double, 3>(const Vec3d& l, const Vec3d& v)>;

ParamValues values_of(const Model& m, const Values& vals) {
  ParamValues pv = ParamValues::defaults(m.params());
  for (const auto& [name, v] : vals)
    for (int c = 0; c < 3; ++c) pv.set(m.params(), name, v.size() == 3 ? v[size_t(c)] : v[0], v.size() == 3 ? c : -1);
  return pv;
}

// Largest relative difference |model − reference| / max(|reference|, 1e-3 · scale) over the
// pairs and channels (scale: the largest reference value, so near-zero values are judged
// against the lobe's size).
double max_relative_difference(const Model& m, const ParamValues& pv, const Reference& reference) {
  const auto pairs = direction_pairs();
  std::vector<std::array<double, 3>> want;
  double scale = 0;
  for (const auto& [l, v] : pairs) {
    want.push_back(reference(l, v));
    for (double x : want.back()) scale = std::max(scale, std::abs(x));
  }
  double worst = 0;
  for (size_t k = 0; k < pairs.size(); ++k)
    for (int c = 0; c < 3; ++c) {
      const double got = m.eval(pv.channel(c), c, pairs[k].first, pairs[k].second);
      const double w = want[k][size_t(c)];
      worst = std::max(worst, std::abs(got - w) / std::max(std::abs(w), 1e-3 * scale));
    }
  return worst;
}

struct Case {
  std::string label;
  Values values;
  Reference reference;
};

void expect_matches(const std::string& model, const std::vector<Case>& cases) {
  const Model& m = model_by_name(model);
  for (const Case& c : cases) {
    const double d = max_relative_difference(m, values_of(m, c.values), c.reference);
    std::printf("%-32s %-28s max relative difference %.2e\n", model.c_str(), c.label.c_str(), d);
    EXPECT_LE(d, 1e-6) << model << " " << c.label;
  }
}
void expect_caught(const std::string& model, const std::string& mistake, const Values& values,
                   const Reference& wrong) {
  const double d = max_relative_difference(model_by_name(model), values_of(model_by_name(model), values), wrong);
  std::printf("%-32s mistake %-40s caught: max relative difference %.2e\n", model.c_str(), mistake.c_str(), d);
  EXPECT_GT(d, 1e-2) << model << ": the comparison does not see " << mistake;
}

ref::Gltf gltf_of(std::array<double, 3> base, double metallic, double roughness, double ior = 1.5,
                  double specular = 1, double sc = 1) {
  return {base, metallic, roughness, ior, specular, sc};
}
Values gltf_values(const ref::Gltf& g) {
  return {{"base_color", {g.base[0], g.base[1], g.base[2]}}, {"metallic", {g.metallic}},
          {"roughness", {g.roughness}}, {"ior", {g.ior}}, {"specular", {g.specular}},
          {"specular_color", {g.specular_color}}};
}

TEST(RendererReference, Gltf) {
  std::vector<Case> cases;
  for (const ref::Gltf& g : {gltf_of({0.8, 0.5, 0.2}, 0.0, 0.5), gltf_of({0.9, 0.6, 0.3}, 1.0, 0.3),
                             gltf_of({0.2, 0.4, 0.7}, 0.4, 0.15, 1.33, 0.7, 0.8),
                             gltf_of({0.05, 0.05, 0.05}, 0.0, 0.9, 2.4, 1.0, 2.5)})
    cases.push_back({"m" + std::to_string(g.metallic) + " r" + std::to_string(g.roughness), gltf_values(g),
                     [g](const Vec3d& l, const Vec3d& v) { return g.eval(l, v, g.roughness * g.roughness); }});
  expect_matches("gltf-metallic-roughness", cases);
}

TEST(RendererReference, GltfMistakesFail) {
  const ref::Gltf g = gltf_of({0.7, 0.5, 0.3}, 0.3, 0.4);
  expect_caught("gltf-metallic-roughness", "roughness squared twice (alpha = r^4)", gltf_values(g),
                [g](const Vec3d& l, const Vec3d& v) { return g.eval(l, v, std::pow(g.roughness, 4)); });
  // An exporter that writes F0 = 0.04 where the IOR belongs: ior 0.04 has F0 = 0.85.
  ref::Gltf f0_as_ior = g;
  f0_as_ior.ior = 0.04;
  expect_caught("gltf-metallic-roughness", "F0 taken as IOR", gltf_values(g), [f0_as_ior](const Vec3d& l, const Vec3d& v) {
    return f0_as_ior.eval(l, v, f0_as_ior.roughness * f0_as_ior.roughness);
  });
  EXPECT_THROW(values_of(model_by_name("gltf-metallic-roughness"), {{"ior", {0.04}}}), InputError);
}

Values conductor_values(std::array<double, 3> eta, std::array<double, 3> k, std::array<double, 3> sr, double alpha) {
  return {{"eta", {eta[0], eta[1], eta[2]}}, {"k", {k[0], k[1], k[2]}},
          {"specular_reflectance", {sr[0], sr[1], sr[2]}}, {"alpha", {alpha}}};
}
Reference mitsuba_conductor_ref(bool beckmann, std::array<double, 3> eta, std::array<double, 3> k,
                                std::array<double, 3> sr, double alpha) {
  return [=](const Vec3d& l, const Vec3d& v) {
    std::array<double, 3> out;
    for (int c = 0; c < 3; ++c) out[size_t(c)] = ref::mitsuba_roughconductor(beckmann, alpha, eta[c], k[c], sr[c], l, v);
    return out;
  };
}

TEST(RendererReference, MitsubaRoughConductor) {
  // Gold-like and aluminium-like indices (RGB), a dielectric-like one, rough and sharp.
  const std::array<double, 3> au_eta{0.143, 0.374, 1.442}, au_k{3.983, 2.385, 1.603};
  const std::array<double, 3> al_eta{1.657, 0.880, 0.521}, al_k{9.224, 6.27, 4.837};
  const std::array<double, 3> one{1, 1, 1};
  for (bool beckmann : {true, false}) {
    const std::string model = beckmann ? "mitsuba-roughconductor-beckmann" : "mitsuba-roughconductor-ggx";
    std::vector<Case> cases;
    cases.push_back({"gold a0.1", conductor_values(au_eta, au_k, one, 0.1),
                     mitsuba_conductor_ref(beckmann, au_eta, au_k, one, 0.1)});
    cases.push_back({"aluminium a0.4 sr0.8", conductor_values(al_eta, al_k, {0.8, 0.7, 0.9}, 0.4),
                     mitsuba_conductor_ref(beckmann, al_eta, al_k, {0.8, 0.7, 0.9}, 0.4)});
    cases.push_back({"dielectric a0.03", conductor_values({1.5, 1.5, 1.5}, {0, 0, 0}, one, 0.03),
                     mitsuba_conductor_ref(beckmann, {1.5, 1.5, 1.5}, {0, 0, 0}, one, 0.03)});
    expect_matches(model, cases);
  }
}

TEST(RendererReference, MitsubaRoughConductorMistakesFail) {
  const std::array<double, 3> eta{0.2, 0.4, 1.4}, k{3.9, 2.4, 1.6}, one{1, 1, 1};
  const Values v = conductor_values(eta, k, one, 0.2);
  expect_caught("mitsuba-roughconductor-ggx", "roughness squared again (alpha = alpha^2)", v,
                mitsuba_conductor_ref(false, eta, k, one, 0.04));
  expect_caught("mitsuba-roughconductor-ggx", "distribution left at Mitsuba's default (beckmann)", v,
                mitsuba_conductor_ref(true, eta, k, one, 0.2));
  // F0 = 0.9 written as eta (k = 0) instead of a conductor index with that F0.
  expect_caught("mitsuba-roughconductor-ggx", "F0 taken as IOR (eta = F0, k = 0)", v,
                mitsuba_conductor_ref(false, {0.9, 0.9, 0.9}, {0, 0, 0}, one, 0.2));
}

Values principled_values(const ref::MitsubaPrincipled& p, std::array<double, 3> base) {
  return {{"base_color", {base[0], base[1], base[2]}}, {"roughness", {p.roughness}}, {"metallic", {p.metallic}},
          {"specular", {p.specular}}, {"sheen", {p.sheen}}, {"clearcoat", {p.clearcoat}},
          {"clearcoat_gloss", {p.clearcoat_gloss}}, {"flatness", {p.flatness}}};
}
Reference principled_ref(ref::MitsubaPrincipled p, std::array<double, 3> base, double alpha) {
  return [=](const Vec3d& l, const Vec3d& v) mutable {
    std::array<double, 3> out;
    for (int c = 0; c < 3; ++c) {
      p.base = base[size_t(c)];
      out[size_t(c)] = p.eval(l, v, alpha);
    }
    return out;
  };
}

TEST(RendererReference, MitsubaPrincipled) {
  std::vector<Case> cases;
  const std::array<double, 3> base{0.8, 0.4, 0.1};
  for (const ref::MitsubaPrincipled& p : {ref::MitsubaPrincipled{0, 0.5, 0.0, 0.5},
                                          ref::MitsubaPrincipled{0, 0.2, 1.0, 0.5},
                                          ref::MitsubaPrincipled{0, 0.35, 0.3, 0.9, 0.6, 0.7, 0.4, 0.5},
                                          ref::MitsubaPrincipled{0, 0.02, 0.0, 0.2, 0.0, 1.0, 1.0, 1.0}})
    cases.push_back({"r" + std::to_string(p.roughness) + " m" + std::to_string(p.metallic), principled_values(p, base),
                     principled_ref(p, base, p.alpha())});
  expect_matches("mitsuba-principled", cases);
}

TEST(RendererReference, MitsubaPrincipledMistakesFail) {
  const std::array<double, 3> base{0.6, 0.5, 0.4};
  const ref::MitsubaPrincipled p{0, 0.4, 0.2, 0.5};
  expect_caught("mitsuba-principled", "roughness squared twice (alpha = r^4)", principled_values(p, base),
                principled_ref(p, base, std::pow(p.roughness, 4)));
  // `specular` 0.5 is F0 = 0.04 through eta ≈ 1.5; writing an IOR of 1.5 into `specular` reads as
  // F0 = 0.12 (clamped specular 1 here).
  ref::MitsubaPrincipled as_ior = p;
  as_ior.specular = 1.0;
  expect_caught("mitsuba-principled", "IOR written as specular", principled_values(p, base),
                principled_ref(as_ior, base, as_ior.alpha()));
}

Reference pbrt_ref(double alpha, std::array<double, 3> eta, std::array<double, 3> k) {
  return [=](const Vec3d& l, const Vec3d& v) {
    std::array<double, 3> out;
    for (int c = 0; c < 3; ++c) out[size_t(c)] = ref::pbrt_conductor(alpha, eta[size_t(c)], k[size_t(c)], l, v);
    return out;
  };
}
Reference pbrt_reflectance_ref(double alpha, std::array<double, 3> r) {
  return pbrt_ref(alpha, {1, 1, 1}, {ref::pbrt_k_from_reflectance(r[0]), ref::pbrt_k_from_reflectance(r[1]),
                                     ref::pbrt_k_from_reflectance(r[2])});
}

TEST(RendererReference, PbrtConductor) {
  std::vector<Case> cases;
  const std::array<double, 3> eta{0.2, 0.92, 1.1}, k{3.91, 2.45, 2.14};
  for (double r : {0.002, 0.05, 0.3, 0.9})
    cases.push_back({"roughness " + std::to_string(r),
                     {{"eta", {eta[0], eta[1], eta[2]}}, {"k", {k[0], k[1], k[2]}}, {"roughness", {r}}},
                     pbrt_ref(std::sqrt(r), eta, k)});
  expect_matches("pbrt-conductor", cases);
  std::vector<Case> refl;
  for (double r : {0.01, 0.2})
    for (const std::array<double, 3>& c : {std::array<double, 3>{0.95, 0.64, 0.54}, {0.04, 0.3, 0.9}})
      refl.push_back({"roughness " + std::to_string(r), {{"reflectance", {c[0], c[1], c[2]}}, {"roughness", {r}}},
                      pbrt_reflectance_ref(std::sqrt(r), c)});
  expect_matches("pbrt-conductor-reflectance", refl);
  // reflectance r is F at normal incidence.
  for (double r : {0.04, 0.5, 0.95}) EXPECT_NEAR(ref::fr_complex(1.0, 1.0, ref::pbrt_k_from_reflectance(r)), r, 1e-12);
}

TEST(RendererReference, PbrtDiffuseAndMix) {
  const std::array<double, 3> R{0.7, 0.5, 0.2}, r{0.9, 0.8, 0.6};
  expect_matches("pbrt-diffuse", {{"R", {{"reflectance", {R[0], R[1], R[2]}}}, [=](const Vec3d& l, const Vec3d& v) {
                                     std::array<double, 3> out{};
                                     for (int c = 0; c < 3; ++c) out[size_t(c)] = l.z() > 0 && v.z() > 0 ? R[size_t(c)] / kPi : 0;
                                     return out;
                                   }}});
  for (double amount : {0.0, 0.3, 1.0}) {
    const auto conductor = pbrt_reflectance_ref(std::sqrt(0.02), r);
    expect_matches("pbrt-mix-diffuse-conductor",
                   {{"amount " + std::to_string(amount),
                     {{"reflectance", {R[0], R[1], R[2]}}, {"amount", {amount}},
                      {"conductor_reflectance", {r[0], r[1], r[2]}}, {"roughness", {0.02}}},
                     [=](const Vec3d& l, const Vec3d& v) {
                       std::array<double, 3> out = conductor(l, v);
                       for (int c = 0; c < 3; ++c) out[size_t(c)] = (1 - amount) * R[size_t(c)] / kPi + amount * out[size_t(c)];
                       return out;
                     }}});
  }
}

TEST(RendererReference, PbrtMistakesFail) {
  const std::array<double, 3> eta{0.2, 0.92, 1.1}, k{3.91, 2.45, 2.14};
  const Values v = {{"eta", {eta[0], eta[1], eta[2]}}, {"k", {k[0], k[1], k[2]}}, {"roughness", {0.09}}};
  expect_caught("pbrt-conductor", "roughness as alpha (remaproughness ignored)", v, pbrt_ref(0.09, eta, k));
  expect_caught("pbrt-conductor", "roughness squared (glTF's convention)", v, pbrt_ref(0.09 * 0.09, eta, k));
  const std::array<double, 3> r{0.9, 0.8, 0.6};
  expect_caught("pbrt-conductor-reflectance", "reflectance taken as eta (k = 0)",
                {{"reflectance", {r[0], r[1], r[2]}}, {"roughness", {0.09}}}, pbrt_ref(0.3, r, {0, 0, 0}));
}

Values disney_values(const ref::Disney& d) {
  return {{"baseColor", {d.baseColor[0], d.baseColor[1], d.baseColor[2]}}, {"metallic", {d.metallic}},
          {"subsurface", {d.subsurface}}, {"specular", {d.specular}}, {"roughness", {d.roughness}},
          {"sheen", {d.sheen}}, {"clearcoat", {d.clearcoat}}, {"clearcoatGloss", {d.clearcoatGloss}}};
}

TEST(RendererReference, Disney) {
  std::vector<Case> cases;
  ref::Disney a{{0.82, 0.67, 0.16}};
  ref::Disney b{{0.9, 0.5, 0.3}, 1.0, 0.0, 0.5, 0.25};
  ref::Disney c{{0.3, 0.6, 0.2}, 0.2, 0.7, 0.8, 0.6, 0, 0, 0.8, 0, 0.9, 0.3};
  ref::Disney d{{0.1, 0.1, 0.1}, 0.0, 0.3, 0.3, 0.02, 0, 0, 0.0, 0, 1.0, 1.0};
  for (const ref::Disney& x : {a, b, c, d})
    cases.push_back({"r" + std::to_string(x.roughness) + " m" + std::to_string(x.metallic), disney_values(x),
                     [x](const Vec3d& l, const Vec3d& v) { return x.BRDF(l, v, x.roughness); }});
  expect_matches("disney-principled", cases);
}

TEST(RendererReference, DisneyMistakesFail) {
  ref::Disney d{{0.7, 0.5, 0.3}, 0.3, 0.0, 0.5, 0.4};
  expect_caught("disney-principled", "roughness squared twice", disney_values(d),
                [d](const Vec3d& l, const Vec3d& v) { return d.BRDF(l, v, d.roughness * d.roughness); });
  ref::Disney linear = d;
  linear.gamma = false;
  expect_caught("disney-principled", "baseColor taken as linear (no mon2lin)", disney_values(d),
                [linear](const Vec3d& l, const Vec3d& v) { return linear.BRDF(l, v, linear.roughness); });
}

}  // namespace
}  // namespace brdfkit
