#pragma once
// The registered Cook-Torrance models as runtime instances (defined in cook_torrance_catalogue.cpp;
// their static types are in cook_torrance_catalogue.h). This header stays free of the ndf/
// headers so registry.cpp does not pull the distributions' names into its translation unit.
#include "brdfkit/models/model.h"

namespace brdfkit {

const Model* cook_torrance_ngan_model();
const Model* cook_torrance_beckmann_model();
const Model* cook_torrance_blinn_phong_model();
const Model* cook_torrance_gaussian_model();
const Model* cook_torrance_ggx_model();
const Model* cook_torrance_gtr_model();
const Model* cook_torrance_exponential_model();
const Model* cook_torrance_sgd_model();
const Model* cook_torrance_exponential_power_model();
const Model* cook_torrance_schlick_rational_model();
const Model* cook_torrance_sawicki_rational_model();

}  // namespace brdfkit
