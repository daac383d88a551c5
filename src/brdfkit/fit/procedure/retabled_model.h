#pragma once
// A model with another parameter table over the same formula and parameter layout: every call goes
// to the inner model, so a fit of it is a fit of the inner model with that table's scopes, boxes
// and defaults (per-channel shapes, the user's search boxes). The inner model's batch evaluations
// (plain, RGB, paired and rescaled) pass through.
#include "brdfkit/models/model.h"
#include "brdfkit/models/paired_evaluation.h"

namespace brdfkit::fit {

class RetabledModel final : public Model, public PairedEvaluation {
 public:
  // `table` has the inner model's parameters in its order; `inner` must outlive this model.
  RetabledModel(const Model& inner, ParamTable table)
      : inner_(inner), paired_(dynamic_cast<const PairedEvaluation*>(&inner)), table_(std::move(table)) {}
  std::string_view name() const override { return inner_.name(); }
  std::string_view description() const override { return inner_.description(); }
  const ParamTable& params() const override { return table_; }
  bool reciprocal() const override { return inner_.reciprocal(); }
  double eval(const double* p, int c, const Vec3d& wi, const Vec3d& wo) const override {
    return inner_.eval(p, c, wi, wo);
  }
  void eval_batch(const double* p, int c, std::size_t n, const SoaPairs& d, double* out) const override {
    inner_.eval_batch(p, c, n, d, out);
  }
  bool eval_batch_pair(const double* p, int c, int param, double a, double b, std::size_t n, const SoaPairs& d,
                       double* out_a, double* out_b) const override {
    return paired_ && paired_->eval_batch_pair(p, c, param, a, b, n, d, out_a, out_b);
  }
  void eval_batch_rgb(const double* const p[3], std::size_t n, const SoaPairs& d, double* const out[3]) const override {
    inner_.eval_batch_rgb(p, n, d, out);
  }
  bool eval_batch_from(const double* p, const double* p0, const double* at_p0, int c, std::size_t n,
                       const SoaPairs& d, double* out) const override {
    return inner_.eval_batch_from(p, p0, at_p0, c, n, d, out);
  }
  std::optional<Vec3d> sample(const double* p, int c, const Vec3d& wo, const Vec2d& u, double u_lobe) const override {
    return inner_.sample(p, c, wo, u, u_lobe);
  }
  double pdf(const double* p, int c, const Vec3d& wo, const Vec3d& wi) const override {
    return inner_.pdf(p, c, wo, wi);
  }

 private:
  const Model& inner_;
  const PairedEvaluation* paired_;
  ParamTable table_;
};

}  // namespace brdfkit::fit
