#pragma once
// One lobe shape per channel (seed 000 §5.1 fits R, G and B separately) with the same solver that
// fits one shared shape: the model's table with every Shared parameter made PerChannel, for a
// RetabledModel. The wrapped model is evaluated with each channel's own values, so a result is a
// valid ParamValues of the model (whose Shared parameters then differ between channels).
#include "brdfkit/models/model.h"

namespace brdfkit::fit {

ParamTable per_channel_shape_table(const Model& model);

}  // namespace brdfkit::fit
