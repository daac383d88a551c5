#pragma once
// A model with some parameters held at given per-channel values: the others form its parameter
// table, so fit_model fits them alone. For procedures that fit a model in stages (seed 004 §5.8
// hp-2step: the diffuse and diffraction lobes first, then the reflection lobe with those fixed).
#include <vector>

#include "brdfkit/models/model.h"

namespace brdfkit::fit {

class FixedParams final : public Model {
 public:
  // `fixed[i]` true holds inner parameter i at `values` (per channel); the rest are free.
  FixedParams(const Model& inner, const std::vector<bool>& fixed, ParamValues values);
  std::string_view name() const override { return inner_.name(); }
  std::string_view description() const override { return inner_.description(); }
  const ParamTable& params() const override { return table_; }
  bool reciprocal() const override { return inner_.reciprocal(); }
  double eval(const double* p, int c, const Vec3d& wi, const Vec3d& wo) const override;
  // Passed through so the inner model's batch path (e.g. HP's once-per-batch Γ(1/p)) serves hp-2step.
  void eval_batch(const double* p, int c, std::size_t n, const SoaPairs& d, double* out) const override;
  std::optional<Vec3d> sample(const double* p, int c, const Vec3d& wo, const Vec2d& u, double u_lobe) const override;
  double pdf(const double* p, int c, const Vec3d& wo, const Vec3d& wi) const override;

  // The free parameters' values (this model's layout) merged into the inner model's.
  ParamValues merged(const ParamValues& free_values) const;
  // The free parameters' part of inner values (for starting points and comparisons).
  ParamValues free_part(const ParamValues& inner_values) const;

 private:
  template <class F> auto with_full(const double* p, int c, F&& f) const;
  const Model& inner_;
  std::vector<int> free_;  // inner index of each of this model's parameters
  ParamValues values_;
  ParamTable table_;
};

}  // namespace brdfkit::fit
