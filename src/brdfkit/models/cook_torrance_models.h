#pragma once
// The registered Cook-Torrance models as runtime instances, in catalogue order (made in
// cook_torrance_catalogue.cpp; their static types are in cook_torrance_catalogue.h). This header
// stays free of the ndf/ headers so registry.cpp does not pull them into its translation unit.
#include <vector>

#include "brdfkit/models/model.h"

namespace brdfkit {

const std::vector<const Model*>& cook_torrance_models();

}  // namespace brdfkit
