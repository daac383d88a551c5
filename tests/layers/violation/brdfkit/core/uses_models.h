#pragma once
// A core header that includes a model: check_layers.cmake must reject it (its own test).
#include "brdfkit/models/model.h"
