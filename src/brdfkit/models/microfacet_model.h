#pragma once
// A runtime Model that also exposes its microfacet distribution D(θh), so checks (`brdfkit
// check`, analysis/model_checks) can integrate ∫ D cosθ dω for any registered microfacet model
// without knowing its static type.
#include <optional>
#include <string_view>

#include "brdfkit/models/model.h"
#include "brdfkit/models/paired_evaluation.h"

namespace brdfkit {

class MicrofacetDistributionView {
 public:
  virtual ~MicrofacetDistributionView() = default;
  // D(θh) of the model's distribution for channel values p (ParamValues::channel order).
  virtual double ndf(const double* p, double cos_theta_h) const = 0;
};

// M: a model type with the static interface of model.h and an `Ndf` template parameter pack
// exposed as M::template Distribution<T> with D(cos θ), built from p + M::kNdfOffset.
// It also offers M's paired evaluation (models/paired_evaluation.h) where M has one.
template <class M>
class MicrofacetModelAdapter final : public ModelAdapter<M>, public MicrofacetDistributionView, public PairedEvaluation {
 public:
  double ndf(const double* p, double cos_theta_h) const override {
    return typename M::template Distribution<double>(p + M::kNdfOffset).D(cos_theta_h);
  }
  bool eval_batch_pair(const double* p, int c, int param, double a, double b, std::size_t n, const SoaPairs& d,
                       double* out_a, double* out_b) const override {
    if constexpr (requires { M::eval_batch_pair(p, c, param, a, b, n, d.wi_x, d.wi_y, d.wi_z, d.wo_x, d.wo_y, d.wo_z,
                                                out_a, out_b); })
      return M::eval_batch_pair(p, c, param, a, b, n, d.wi_x, d.wi_y, d.wi_z, d.wo_x, d.wo_y, d.wo_z, out_a, out_b);
    else
      return false;
  }
};

}  // namespace brdfkit
