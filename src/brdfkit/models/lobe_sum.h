#pragma once
// Multi-lobe models (DESIGN.md §6 "multi-lobe"): a diffuse term plus the specular
// lobes of any registered models, e.g. two Cook-Torrance lobes (seed 002 §4.2) or Lambert + Ward
// + Blinn-Phong, built at run time and addressed by the names of its components joined with '+':
// `cook-torrance-beckmann+cook-torrance-beckmann`, `lambert+ward+blinn-phong`.
//
// ρ = Σⱼ ρⱼ(pⱼ) with ONE diffuse term. Every model of the catalogue names its Lambertian albedo
// `kd`; the first component that has a `kd` supplies the sum's diffuse term, listed unprefixed as
// `kd`, and the `kd` of every later component is held at 0 (dropped from the table, so no fit can
// move it and variable projection sees one diffuse colour). Every other parameter is listed as
// `<j>.<name>` with the component's 1-based position j: `1.ks`, `1.alpha`, `2.ks`, `2.alpha`.
// Bounds, scope, linear flag and doc are the component's, so variable projection finds the same
// linear colours (kd + each lobe's scales). A component left with no parameter (a second
// `lambert`) is refused. Lobes of one kind would start a fit from identical shapes, a symmetric
// point the solver cannot leave, so the k-th repetition of a model starts its non-linear
// parameters moved (k − 1) times by 35 % of the way towards their lower bound (geometrically, by at
// most a factor 3, as tests/models/param_sets.h moves them).
//
// Sampling picks component j with probability ∝ its albedo estimate at wo (seed 004 §5.5,
// models/lobe_mixture.h), draws from the component's own sampler and reports the mixture density
// Σⱼ Pⱼ pdfⱼ. The estimate is a fixed 16-point importance-sampled albedo of each component
// (deterministic in p, c and wo, so sample and pdf agree), with a 2 % uniform share so that a
// component whose estimate is 0 still covers its support.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "brdfkit/models/model.h"

namespace brdfkit {

class LobeSum final : public Model {
 public:
  static constexpr size_t kMaxComponents = 8;
  static constexpr size_t kMaxComponentParams = 32;

  // Throws InputError (naming the sum) for fewer than 2 or more than kMaxComponents components,
  // or a component that would be left without parameters.
  explicit LobeSum(std::vector<const Model*> components);

  // "a+b+…": every part a registered model (model_by_name); InputError naming the bad part.
  static std::unique_ptr<LobeSum> from_name(std::string_view name);
  static bool is_sum_name(std::string_view name) { return name.find('+') != std::string_view::npos; }

  std::string_view name() const override { return name_; }
  std::string_view description() const override { return description_; }
  const ParamTable& params() const override { return table_; }
  bool reciprocal() const override { return reciprocal_; }
  double eval(const double* p, int c, const Vec3d& wi, const Vec3d& wo) const override;
  std::optional<Vec3d> sample(const double* p, int c, const Vec3d& wo, const Vec2d& u, double u_lobe) const override;
  double pdf(const double* p, int c, const Vec3d& wo, const Vec3d& wi) const override;

  size_t component_count() const { return components_.size(); }
  const Model& component(size_t j) const { return *components_[j].model; }
  // Component j's parameter vector (its own table order) from the sum's values p; `out` holds at
  // least kMaxComponentParams values.
  void component_params(size_t j, const double* p, double* out) const;
  // Index in the sum's table of component j's parameter i, or −1 when it is held at 0.
  int source_index(size_t j, size_t i) const { return components_[j].source[i]; }
  // The probabilities with which `sample` picks each component at wo (the first
  // component_count() entries are used).
  std::array<double, kMaxComponents> selection_probabilities(const double* p, int c, const Vec3d& wo) const;

 private:
  struct Component {
    const Model* model;
    std::vector<int> source;  // sum-table index of each of the component's parameters, −1: held at 0
  };
  std::array<double, kMaxComponents> compute_probabilities(const double* p, int c, const Vec3d& wo) const;
  static std::uint64_t next_id();

  std::string name_, description_;
  ParamTable table_;
  std::vector<Component> components_;
  bool reciprocal_ = true;
  std::uint64_t id_;  // tells this sum's cached selection probabilities from another's
};

}  // namespace brdfkit
