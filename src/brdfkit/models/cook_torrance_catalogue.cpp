// Runtime instances of the Cook-Torrance catalogue (one translation unit for all instantiations).
#include "brdfkit/models/cook_torrance_catalogue.h"

#include "brdfkit/models/microfacet_model.h"

namespace brdfkit {

namespace {
template <class M> const Model* microfacet_instance() {
  static const MicrofacetModelAdapter<M> m;
  return &m;
}
}  // namespace

const Model* cook_torrance_ngan_model() { return microfacet_instance<CookTorranceNgan>(); }
const Model* cook_torrance_beckmann_model() { return microfacet_instance<CookTorranceBeckmann>(); }
const Model* cook_torrance_blinn_phong_model() { return microfacet_instance<CookTorranceBlinnPhong>(); }
const Model* cook_torrance_gaussian_model() { return microfacet_instance<CookTorranceGaussian>(); }
const Model* cook_torrance_ggx_model() { return microfacet_instance<CookTorranceGgx>(); }
const Model* cook_torrance_gtr_model() { return microfacet_instance<CookTorranceGtr>(); }
const Model* cook_torrance_exponential_model() { return microfacet_instance<CookTorranceExponential>(); }
const Model* cook_torrance_sgd_model() { return microfacet_instance<CookTorranceSgd>(); }
const Model* cook_torrance_exponential_power_model() { return microfacet_instance<CookTorranceExponentialPower>(); }
const Model* cook_torrance_schlick_rational_model() { return microfacet_instance<CookTorranceSchlickRational>(); }
const Model* cook_torrance_sawicki_rational_model() { return microfacet_instance<CookTorranceSawickiRational>(); }

}  // namespace brdfkit
