#pragma once
// Synthetic measured materials for the fit tests: an analytic model as a MeasuredBrdf (exact
// values anywhere) and MERL-format tables tabulated from known parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "brdfkit/fit/settings/fit_settings.h"
#include "brdfkit/measured/merl_brdf.h"
#include "brdfkit/measured/merl_tabulate.h"
#include "brdfkit/measured/sample_set.h"
#include "brdfkit/models/model.h"

namespace brdfkit::test {

class AnalyticMeasured final : public MeasuredBrdf {
 public:
  AnalyticMeasured(const Model& model, ParamValues values) : brdf_(model, std::move(values)) {}
  std::string format() const override { return "analytic"; }
  std::string path() const override { return "analytic:" + std::string(brdf_.model().name()); }
  std::string dimensions() const override { return "continuous"; }
  std::optional<Rgb> eval(const Vec3d& wi, const Vec3d& wo) const override {
    if (!(wi.z() > 0 && wo.z() > 0)) return std::nullopt;
    return brdf_.eval(wi, wo);
  }
  SampleSet samples() const override { return {}; }

 private:
  Brdf brdf_;
};

// Parameter values from name → (R, G, B) lists; unspecified parameters keep their defaults.
inline ParamValues make_values(const Model& m, std::initializer_list<std::pair<const char*, Rgb>> vals) {
  ParamValues v = ParamValues::defaults(m.params());
  for (const auto& [name, rgb] : vals) {
    const int i = find_param(m.params(), name);
    EXPECT_GE(i, 0) << name;
    for (int c = 0; c < 3; ++c) v.values[size_t(c)][size_t(i)] = rgb[c];
  }
  return v;
}

// Holzschuch-Pacanowski with a visible diffraction lobe (σ = 0.05, p = 0.6, a = 1): the material
// of the hp-2step tests.
inline ParamValues hp_diffraction_material(const Model& m) {
  return make_values(m, {{"kd", Rgb(0.05, 0.04, 0.03)},
                         {"ks", Rgb(0.6, 0.5, 0.4)},
                         {"kw", Rgb(0.02, 0.01, 0.005)},
                         {"sigma", Rgb::Constant(0.05)},
                         {"p", Rgb::Constant(0.6)},
                         {"a", Rgb::Constant(1.0)},
                         {"F0", Rgb(0.05, 0.05, 0.05)}});
}

// A MERL table of the model, with a fraction of the cells marked "not measured" and
// multiplicative Gaussian noise of relative size `noise`, both seeded.
inline merl::Table tabulate_model(const Model& m, const ParamValues& v, double missing = 0, double noise = 0,
                                  std::uint64_t seed = 7) {
  const Brdf brdf(m, v);
  merl::Table t = merl::tabulate([&](const Vec3d& wi, const Vec3d& wo) { return brdf.eval(wi, wo); });
  if (missing > 0 || noise > 0) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::normal_distribution<double> g(0, 1);
    for (size_t k = 0; k < merl::kCellCount; ++k) {
      if (!t.valid(k)) continue;
      const bool drop = u(rng) < missing;
      Rgb r(t.raw(0, k), t.raw(1, k), t.raw(2, k));
      if (noise > 0) r *= (1.0 + noise * g(rng));
      if (drop) r = Rgb::Constant(-1.0);
      t.set_raw(k, r[0], r[1], r[2]);
    }
  }
  return t;
}

// Settings naming a procedure (fit/procedure/procedure.h).
// Directional albedo at θi = 10°, 20° … 80° of scattered samples laid out on those incidence
// rings: Σ ρ cosθo w over each ring's samples (weights of one ring summing to 2π, or to 2π in all
// over several azimuths of one θi, whose average albedo this then is).
inline std::vector<std::pair<double, Rgb>> ten_degree_ring_albedos(const SampleSet& s) {
  std::vector<std::pair<double, Rgb>> out;
  for (int i = 1; i <= 8; ++i) {
    const double theta = i * 10 * kPi / 180;
    Rgb a = Rgb::Zero();
    for (size_t k = 0; k < s.size(); ++k)
      if (std::abs(std::acos(s.wi_z[k]) - theta) < 1e-9) a += s.value(k) * s.wo_z[k] * s.weight[k];
    out.emplace_back(theta, a);
  }
  return out;
}

// Samples laid out on the ten-degree incidence rings as a scattered measured file: eval() answers
// nothing, as for a real one; the albedo comes from the samples (ten_degree_ring_albedos).
class ScatteredData final : public MeasuredBrdf {
 public:
  ScatteredData(SampleSet samples, std::string path) : samples_(std::move(samples)), path_(std::move(path)) {}
  std::string format() const override { return "scattered"; }
  std::string path() const override { return path_; }
  std::string dimensions() const override { return std::to_string(samples_.size()) + " samples"; }
  std::optional<Rgb> eval(const Vec3d&, const Vec3d&) const override { return std::nullopt; }
  SampleSet samples() const override { return samples_; }
  std::vector<std::pair<double, Rgb>> albedos_from_samples() const override { return ten_degree_ring_albedos(samples_); }

 private:
  SampleSet samples_;
  std::string path_;
};

inline fit::FitSettings with_procedure(fit::FitSettings s, const std::string& id) {
  s.procedure = id;
  return s;
}

}  // namespace brdfkit::test
