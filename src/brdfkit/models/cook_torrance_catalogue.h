#pragma once
// The registered Cook-Torrance models: `cook-torrance` (Ngan et al. 2005's form: Beckmann,
// Schlick Fresnel, Cook-Torrance V-groove masking; seed 002 §4) and one `cook-torrance-<ndf>`
// per distribution of ndf/ (Schlick Fresnel, uncorrelated Smith masking, seed 004 Eq. 1).
// The types are here for tests and fitting code that need the static model (Jets, batches);
// the runtime instances live in cook_torrance_catalogue.cpp so the many instantiations are
// compiled in one translation unit.
#include <tuple>

#include "brdfkit/fresnel/schlick.h"
#include "brdfkit/models/cook_torrance.h"
#include "brdfkit/models/model.h"
#include "brdfkit/models/named_model.h"
#include "brdfkit/ndf/beckmann.h"
#include "brdfkit/ndf/ggx.h"

namespace brdfkit {

using CookTorranceNgan = Named<CookTorrance<Beckmann, SchlickFresnel, Masking::VGroove>, "cook-torrance",
                               "kd/pi + Cook-Torrance: Beckmann D, Schlick F, V-groove G (Ngan 2005)">;
using CookTorranceBeckmann = Named<CookTorrance<Beckmann, SchlickFresnel>, "cook-torrance-beckmann",
                                   "kd/pi + ks F D G/(4 cos_i cos_o): Beckmann D, Schlick F, Smith G">;
using CookTorranceGgx = Named<CookTorrance<Ggx, SchlickFresnel>, "cook-torrance-ggx",
                              "kd/pi + ks F D G/(4 cos_i cos_o): GGX D, Schlick F, Smith G">;

// Every registered Cook-Torrance type, in registry order (tests iterate over it).
using CookTorranceCatalogue = std::tuple<CookTorranceNgan, CookTorranceBeckmann, CookTorranceGgx>;

// The runtime instances registry.cpp lists (MicrofacetModelAdapter of the types above).
const Model* cook_torrance_ngan_model();
const Model* cook_torrance_beckmann_model();
const Model* cook_torrance_ggx_model();

}  // namespace brdfkit
