#include "brdfkit/models/low_microfacet.h"

namespace brdfkit {

const Model* low_microfacet_model() {
  static const ModelAdapter<LowMicrofacet> m;
  return &m;
}

}  // namespace brdfkit
