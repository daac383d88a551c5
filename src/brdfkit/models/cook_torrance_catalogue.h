#pragma once
// The registered Cook-Torrance models: `cook-torrance` (Ngan et al. 2005's form: Beckmann,
// Schlick Fresnel, Cook-Torrance V-groove masking; seed 002 §4) and one `cook-torrance-<ndf>`
// per normalized distribution of ndf/ (Schlick Fresnel, uncorrelated Smith masking, seed 004
// Eq. 1). Not here: the ABC facet (unnormalized, Löw's microfacet model has its own form) and
// the tabulated distribution (no parameters: it is built from data).
// The types are here for tests and fitting code that need the static model (Jets, batches);
// the runtime instances live in cook_torrance_catalogue.cpp so the many instantiations are
// compiled in one translation unit.
#include <tuple>

#include "brdfkit/fresnel/schlick.h"
#include "brdfkit/models/cook_torrance.h"
#include "brdfkit/models/cook_torrance_models.h"
#include "brdfkit/models/model.h"
#include "brdfkit/models/named_model.h"
#include "brdfkit/ndf/beckmann.h"
#include "brdfkit/ndf/blinn_phong.h"
#include "brdfkit/ndf/exponential.h"
#include "brdfkit/ndf/exponential_power.h"
#include "brdfkit/ndf/gaussian.h"
#include "brdfkit/ndf/ggx.h"
#include "brdfkit/ndf/gtr.h"
#include "brdfkit/ndf/sawicki_rational.h"
#include "brdfkit/ndf/schlick_rational.h"
#include "brdfkit/ndf/sgd.h"

namespace brdfkit {

using CookTorranceNgan = Named<CookTorrance<Beckmann, SchlickFresnel, Masking::VGroove>, "cook-torrance",
                               "kd/pi + Cook-Torrance: Beckmann D, Schlick F, V-groove G (Ngan 2005)">;
#define BRDFKIT_CT_DESCRIPTION(D) "kd/pi + ks F D G/(4 cos_i cos_o): " D " D, Schlick F, uncorrelated Smith G"
using CookTorranceBeckmann =
    Named<CookTorrance<Beckmann, SchlickFresnel>, "cook-torrance-beckmann", BRDFKIT_CT_DESCRIPTION("Beckmann")>;
using CookTorranceBlinnPhong = Named<CookTorrance<BlinnPhong, SchlickFresnel>, "cook-torrance-blinn-phong",
                                     BRDFKIT_CT_DESCRIPTION("Blinn-Phong")>;
using CookTorranceGaussian =
    Named<CookTorrance<Gaussian, SchlickFresnel>, "cook-torrance-gaussian", BRDFKIT_CT_DESCRIPTION("Gaussian")>;
using CookTorranceGgx = Named<CookTorrance<Ggx, SchlickFresnel>, "cook-torrance-ggx", BRDFKIT_CT_DESCRIPTION("GGX")>;
using CookTorranceGtr = Named<CookTorrance<Gtr, SchlickFresnel>, "cook-torrance-gtr", BRDFKIT_CT_DESCRIPTION("GTR")>;
using CookTorranceExponential = Named<CookTorrance<Exponential, SchlickFresnel>, "cook-torrance-exponential",
                                      BRDFKIT_CT_DESCRIPTION("exponential")>;
using CookTorranceSgd = Named<CookTorrance<Sgd, SchlickFresnel>, "cook-torrance-sgd", BRDFKIT_CT_DESCRIPTION("SGD")>;
using CookTorranceExponentialPower = Named<CookTorrance<ExponentialPower, SchlickFresnel>,
                                           "cook-torrance-exponential-power", BRDFKIT_CT_DESCRIPTION("exponential power")>;
using CookTorranceSchlickRational = Named<CookTorrance<SchlickRational, SchlickFresnel>,
                                          "cook-torrance-schlick-rational", BRDFKIT_CT_DESCRIPTION("Schlick rational")>;
using CookTorranceSawickiRational = Named<CookTorrance<SawickiRational, SchlickFresnel>,
                                          "cook-torrance-sawicki-rational", BRDFKIT_CT_DESCRIPTION("Sawicki rational")>;
#undef BRDFKIT_CT_DESCRIPTION

// Every registered Cook-Torrance type, in registry order (tests iterate over it).
using CookTorranceCatalogue =
    std::tuple<CookTorranceNgan, CookTorranceBeckmann, CookTorranceBlinnPhong, CookTorranceGaussian, CookTorranceGgx,
               CookTorranceGtr, CookTorranceExponential, CookTorranceSgd, CookTorranceExponentialPower,
               CookTorranceSchlickRational, CookTorranceSawickiRational>;

}  // namespace brdfkit
