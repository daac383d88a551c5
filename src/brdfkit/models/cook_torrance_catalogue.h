#pragma once
// The registered Cook-Torrance models: `cook-torrance` (Ngan et al. 2005's form: Beckmann,
// Schlick Fresnel, Cook-Torrance V-groove masking; seed 002 §4) and one `cook-torrance-<name>` per
// distribution of ndf/distributions.h (Schlick Fresnel, uncorrelated Smith masking, seed 004
// Eq. 1). Not here: the ABC facet (unnormalized, Löw's microfacet model has its own form) and the
// tabulated distribution (no parameters: it is built from data).
// The static types are here for tests and benchmarks that need them (Jets, batches); the runtime
// instances are made in cook_torrance_catalogue.cpp, one translation unit for all instantiations.
#include <string>
#include <string_view>
#include <tuple>

#include "brdfkit/fresnel/schlick.h"
#include "brdfkit/models/cook_torrance.h"
#include "brdfkit/models/named_model.h"
#include "brdfkit/ndf/distributions.h"

namespace brdfkit {

using CookTorranceNgan = Named<CookTorrance<Beckmann, SchlickFresnel, Masking::VGroove>, "cook-torrance",
                               "kd/pi + Cook-Torrance: Beckmann D, Schlick F, V-groove G (Ngan 2005)">;

// Cook-Torrance with distribution Ndf, Schlick Fresnel and uncorrelated Smith masking, named after Ndf.
template <template <class> class Ndf> struct CookTorranceWith : CookTorrance<Ndf, SchlickFresnel> {
  static std::string_view name() {
    static const std::string n = "cook-torrance-" + std::string(Ndf<double>::kName);
    return n;
  }
  static std::string_view description() {
    static const std::string d = "kd/pi + ks F D G/(4 cos_i cos_o): " + std::string(Ndf<double>::kTitle) +
                                 " D, Schlick F, uncorrelated Smith G";
    return d;
  }
};

using CookTorranceBeckmann = CookTorranceWith<Beckmann>;
using CookTorranceGgx = CookTorranceWith<Ggx>;

// Every registered Cook-Torrance type, in registry order (tests iterate over it).
template <template <class> class... Ds> using CookTorranceTuple = std::tuple<CookTorranceNgan, CookTorranceWith<Ds>...>;
using CookTorranceCatalogue = Distributions::apply<CookTorranceTuple>;

}  // namespace brdfkit
