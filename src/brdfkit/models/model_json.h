#pragma once
// A model as `brdfkit models --json` lists it and Python's Model.params gives it: name,
// description, reciprocity and the parameter table (bounds, default, scope, linearity, doc).
#include <nlohmann/json.hpp>

#include "brdfkit/models/model.h"

namespace brdfkit {

nlohmann::json model_json(const Model& model);

}  // namespace brdfkit
