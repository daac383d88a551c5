#include "brdfkit/fit/procedure/per_channel_shape.h"

namespace brdfkit::fit {

PerChannelShape::PerChannelShape(const Model& inner) : inner_(inner), table_(inner.params()) {
  for (ParamSpec& s : table_) s.scope = Scope::PerChannel;
}

}  // namespace brdfkit::fit
