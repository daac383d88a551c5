#include "brdfkit/models/holzschuch_pacanowski.h"

#include "brdfkit/models/microfacet_model.h"

namespace brdfkit {

const Model* holzschuch_pacanowski_model() {
  static const MicrofacetModelAdapter<HolzschuchPacanowski> m;
  return &m;
}

}  // namespace brdfkit
