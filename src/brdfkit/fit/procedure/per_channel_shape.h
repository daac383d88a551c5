#pragma once
// A model whose Shared parameters (the lobe shape) become PerChannel ones: fitting it fits one
// shape per channel (seed 000 §5.1 fits R, G and B separately) with the same solver that fits
// one shared shape. The wrapped model is evaluated with each channel's own values, so a result is
// a valid ParamValues of the wrapped model (whose Shared parameters then differ between channels).
#include "brdfkit/models/model.h"

namespace brdfkit::fit {

class PerChannelShape final : public Model {
 public:
  explicit PerChannelShape(const Model& inner);
  std::string_view name() const override { return inner_.name(); }
  std::string_view description() const override { return inner_.description(); }
  const ParamTable& params() const override { return table_; }
  bool reciprocal() const override { return inner_.reciprocal(); }
  double eval(const double* p, int c, const Vec3d& wi, const Vec3d& wo) const override {
    return inner_.eval(p, c, wi, wo);
  }
  std::optional<Vec3d> sample(const double* p, int c, const Vec3d& wo, const Vec2d& u, double u_lobe) const override {
    return inner_.sample(p, c, wo, u, u_lobe);
  }
  double pdf(const double* p, int c, const Vec3d& wo, const Vec3d& wi) const override {
    return inner_.pdf(p, c, wo, wi);
  }
  const Model& inner() const { return inner_; }

 private:
  const Model& inner_;
  ParamTable table_;
};

}  // namespace brdfkit::fit
