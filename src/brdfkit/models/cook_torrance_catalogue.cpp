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
const Model* cook_torrance_ggx_model() { return microfacet_instance<CookTorranceGgx>(); }

}  // namespace brdfkit
