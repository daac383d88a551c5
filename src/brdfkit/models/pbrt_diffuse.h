#pragma once
// pbrt-v4's `diffuse` material (mmp/pbrt-v4 at commit 5f7a6068: src/pbrt/bxdfs.h DiffuseBxDF::f,
// src/pbrt/materials.h DiffuseMaterial::GetBxDF): ρ = R/π with R = `reflectance` clamped to [0, 1].
// Lambert's evaluation and sampling under pbrt's parameter name, so exports read the name pbrt uses.
#include <string_view>

#include "brdfkit/models/lambert.h"

namespace brdfkit {

struct PbrtDiffuse : Lambert {
  static std::string_view name() { return "pbrt-diffuse"; }
  static std::string_view description() { return "pbrt-v4 diffuse, reflectance/pi (DiffuseBxDF, bxdfs.h)"; }
  static ParamTable params() {
    return {{"reflectance", 0.0, 1.0, 0.5, Scope::PerChannel, true, "pbrt reflectance R of R/pi"}};
  }
};

}  // namespace brdfkit
