#pragma once
// A runtime Model that also exposes its microfacet distribution D(θh), so checks (`brdfkit
// check`, analysis/model_checks) can integrate ∫ D cosθ dω for any registered microfacet model
// without knowing its static type. Same behaviour as ModelAdapter<M> otherwise.
#include <optional>
#include <string_view>

#include "brdfkit/models/model.h"

namespace brdfkit {

class MicrofacetDistributionView {
 public:
  virtual ~MicrofacetDistributionView() = default;
  // D(θh) of the model's distribution for channel values p (ParamValues::channel order).
  virtual double ndf(const double* p, double cos_theta_h) const = 0;
};

// M: a model type with the static interface of model.h and an `Ndf` template parameter pack
// exposed as M::template Distribution<T> with D(cos θ), built from p + M::kNdfOffset.
template <class M> class MicrofacetModelAdapter final : public Model, public MicrofacetDistributionView {
 public:
  MicrofacetModelAdapter() : table_(M::params()) {}
  std::string_view name() const override { return M::name(); }
  std::string_view description() const override { return M::description(); }
  const ParamTable& params() const override { return table_; }
  bool reciprocal() const override { return M::kReciprocal; }
  double eval(const double* p, int c, const Vec3d& wi, const Vec3d& wo) const override {
    return M::template eval<double>(p, c, wi, wo);
  }
  std::optional<Vec3d> sample(const double* p, int c, const Vec3d& wo, const Vec2d& u, double u_lobe) const override {
    return M::sample(p, c, wo, u, u_lobe);
  }
  double pdf(const double* p, int c, const Vec3d& wo, const Vec3d& wi) const override { return M::pdf(p, c, wo, wi); }
  double ndf(const double* p, double cos_theta_h) const override {
    return typename M::template Distribution<double>(p + M::kNdfOffset).D(cos_theta_h);
  }

 private:
  ParamTable table_;
};

}  // namespace brdfkit
