#pragma once
// One interface for every analytic BRDF model (the shape of pbrt-v4's BxDF interface).
//
// A concrete model is a small value type M with
//   static std::string_view name(), description();  static ParamTable params();
//   static constexpr bool kReciprocal;
//   template <class T> static T eval(const T* p, int c, const Vec3<T>& wi, const Vec3<T>& wo);
//   static std::optional<Vec3d> sample(const double* p, int c, const Vec3d& wo, const Vec2d& u, double u_lobe);
//   static double pdf(const double* p, int c, const Vec3d& wo, const Vec3d& wi);
// and optionally its own structure-of-arrays loop (when the plain loop over eval<double> does
// not vectorize, e.g. terms that do not depend on the pair are hoisted out of it):
//   static void eval_batch(const double* p, int c, size_t n, const double* wi_x, wi_y, wi_z,
//                          wo_x, wo_y, wo_z, double* out);
// and, where the three channels share costly terms (Model::eval_batch_rgb):
//   static void eval_batch_rgb(const double* const p[3], size_t n, wi_x, …, wo_z, double* const out[3]);
// and, for parameters that only scale a costly term by a cheap factor (Model::eval_batch_from):
//   static bool eval_batch_from(const double* p, const double* p0, const double* at_p0, int c,
//                               size_t n, wi_x, …, wo_z, double* out);
// where p holds channel c's value of every parameter (ParamValues::channel). `eval` is one template
// for doubles, SIMD-friendly loops and Ceres Jets (tests check the Jets against differences of
// the doubles). ModelAdapter<M> turns such a type into the runtime Model the CLI, reports,
// fitting and Python use; whole domains are evaluated through Model::eval_batch (one virtual
// call per batch, DESIGN.md §12).
#include <concepts>
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "brdfkit/core/registry.h"
#include "brdfkit/core/vec.h"
#include "brdfkit/core/param.h"

namespace brdfkit {

// n direction pairs in structure-of-arrays form (DESIGN.md §12): pair k is
// wi = (wi_x[k], wi_y[k], wi_z[k]), wo = (wo_x[k], wo_y[k], wo_z[k]), unit vectors.
struct SoaPairs {
  const double *wi_x, *wi_y, *wi_z, *wo_x, *wo_y, *wo_z;
};

class Model {
 public:
  virtual ~Model() = default;
  virtual std::string_view name() const = 0;
  virtual std::string_view description() const = 0;
  virtual const ParamTable& params() const = 0;
  virtual bool reciprocal() const = 0;
  // ρ(wi, wo) of channel c in sr⁻¹; wi towards the light, wo towards the viewer.
  virtual double eval(const double* p, int c, const Vec3d& wi, const Vec3d& wo) const = 0;
  // out[k] = eval(p, c, wi_k, wo_k) for k < n, the same values. This default loops over the
  // virtual eval; ModelAdapter<M> overrides it with M's inlined (vectorizable) loop.
  virtual void eval_batch(const double* p, int c, std::size_t n, const SoaPairs& d, double* out) const {
    for (std::size_t k = 0; k < n; ++k)
      out[k] = eval(p, c, Vec3d(d.wi_x[k], d.wi_y[k], d.wi_z[k]), Vec3d(d.wo_x[k], d.wo_y[k], d.wo_z[k]));
  }
  // out[c][k] = eval_batch(p[c], c, …)'s out[k] for the channels c = 0, 1, 2, the same values.
  // This default makes the three calls; ModelAdapter<M> calls M's own where the channels share
  // costly terms (He computes its slope and effective roughness once for the three).
  virtual void eval_batch_rgb(const double* const p[3], std::size_t n, const SoaPairs& d, double* const out[3]) const {
    for (int c = 0; c < 3; ++c) eval_batch(p[c], c, n, d, out[c]);
  }
  // out[k] = ρ at p from at_p0[k] = ρ at p0 (eval_batch's values for the same pairs), without
  // the model's costly terms, where p differs from p0 only in parameters that scale such a term by
  // a cheap factor (He's complex index, which enters through its Fresnel factor alone): what a
  // finite difference in such a parameter costs. Equal to eval_batch to rounding. False, with
  // nothing written, where the model has no such shortcut for these parameters.
  virtual bool eval_batch_from(const double* /*p*/, const double* /*p0*/, const double* /*at_p0*/, int /*c*/,
                               std::size_t /*n*/, const SoaPairs& /*d*/, double* /*out*/) const {
    return false;
  }
  // Draws wi given wo (u uniform in [0,1)², u_lobe uniform in [0,1) picks a lobe); nullopt when
  // the draw lands below the horizon (its probability mass is part of pdf's deficit).
  virtual std::optional<Vec3d> sample(const double* p, int c, const Vec3d& wo, const Vec2d& u,
                                      double u_lobe) const = 0;
  // Density of `sample` over wi (solid angle measure).
  virtual double pdf(const double* p, int c, const Vec3d& wo, const Vec3d& wi) const = 0;
};

template <class M> class ModelAdapter : public Model {
 public:
  ModelAdapter() : table_(M::params()) {}
  std::string_view name() const override { return M::name(); }
  std::string_view description() const override { return M::description(); }
  const ParamTable& params() const override { return table_; }
  bool reciprocal() const override { return M::kReciprocal; }
  double eval(const double* p, int c, const Vec3d& wi, const Vec3d& wo) const override {
    return M::template eval<double>(p, c, wi, wo);
  }
  void eval_batch(const double* p, int c, std::size_t n, const SoaPairs& d, double* out) const override {
    if constexpr (requires { M::eval_batch(p, c, n, d.wi_x, d.wi_y, d.wi_z, d.wo_x, d.wo_y, d.wo_z, out); }) {
      M::eval_batch(p, c, n, d.wi_x, d.wi_y, d.wi_z, d.wo_x, d.wo_y, d.wo_z, out);
    } else {
      for (std::size_t k = 0; k < n; ++k)
        out[k] = M::template eval<double>(p, c, Vec3d(d.wi_x[k], d.wi_y[k], d.wi_z[k]),
                                          Vec3d(d.wo_x[k], d.wo_y[k], d.wo_z[k]));
    }
  }
  void eval_batch_rgb(const double* const p[3], std::size_t n, const SoaPairs& d, double* const out[3]) const override {
    if constexpr (requires { M::eval_batch_rgb(p, n, d.wi_x, d.wi_y, d.wi_z, d.wo_x, d.wo_y, d.wo_z, out); })
      M::eval_batch_rgb(p, n, d.wi_x, d.wi_y, d.wi_z, d.wo_x, d.wo_y, d.wo_z, out);
    else
      Model::eval_batch_rgb(p, n, d, out);
  }
  bool eval_batch_from(const double* p, const double* p0, const double* at_p0, int c, std::size_t n,
                       const SoaPairs& d, double* out) const override {
    if constexpr (requires { M::eval_batch_from(p, p0, at_p0, c, n, d.wi_x, d.wi_y, d.wi_z, d.wo_x, d.wo_y, d.wo_z, out); })
      return M::eval_batch_from(p, p0, at_p0, c, n, d.wi_x, d.wi_y, d.wi_z, d.wo_x, d.wo_y, d.wo_z, out);
    else
      return false;
  }
  std::optional<Vec3d> sample(const double* p, int c, const Vec3d& wo, const Vec2d& u, double u_lobe) const override {
    return M::sample(p, c, wo, u, u_lobe);
  }
  double pdf(const double* p, int c, const Vec3d& wo, const Vec3d& wi) const override { return M::pdf(p, c, wo, wi); }

 private:
  ParamTable table_;
};

// A model with parameter values: what users evaluate, sample, print and save.
class Brdf {
 public:
  Brdf(const Model& model, ParamValues values) : model_(&model), values_(std::move(values)) {}
  const Model& model() const { return *model_; }
  const ParamValues& values() const { return values_; }

  Rgb eval(const Vec3d& wi, const Vec3d& wo) const;
  // Sampling for RGB: a channel is picked uniformly (u_lobe is reused), so the density is the
  // mean of the channels' densities; with shared lobe shapes all three coincide.
  std::optional<Vec3d> sample(const Vec3d& wo, const Vec2d& u, double u_lobe) const;
  double pdf(const Vec3d& wo, const Vec3d& wi) const;

 private:
  const Model* model_;
  ParamValues values_;
};

// The catalogue: every model by name, in the order `brdfkit models` lists them.
const Registry<const Model*>& model_registry();
// Every model of the catalogue, in that order.
std::span<const Model* const> all_models();
// The model called `name`; throws InputError listing the known names otherwise.
const Model& model_by_name(std::string_view name);

}  // namespace brdfkit
