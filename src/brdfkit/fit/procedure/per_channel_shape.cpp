#include "brdfkit/fit/procedure/per_channel_shape.h"

namespace brdfkit::fit {

ParamTable per_channel_shape_table(const Model& model) {
  ParamTable table = model.params();
  for (ParamSpec& s : table) s.scope = Scope::PerChannel;
  return table;
}

}  // namespace brdfkit::fit
