#pragma once
// A runtime Model that also exposes its microfacet distribution D(θh), so checks (`brdfkit
// check`, analysis/model_checks) can integrate ∫ D cosθ dω for any registered microfacet model
// without knowing its static type.
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
template <class M> class MicrofacetModelAdapter final : public ModelAdapter<M>, public MicrofacetDistributionView {
 public:
  double ndf(const double* p, double cos_theta_h) const override {
    return typename M::template Distribution<double>(p + M::kNdfOffset).D(cos_theta_h);
  }
};

}  // namespace brdfkit
