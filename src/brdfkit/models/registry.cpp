// The catalogue: every model brdfkit knows, in the order `brdfkit models` lists them.
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "brdfkit/core/error.h"
#include "brdfkit/core/registry.h"
#include "brdfkit/models/cook_torrance_anisotropic.h"
#include "brdfkit/models/cook_torrance_models.h"
#include "brdfkit/models/ashikhmin_shirley.h"
#include "brdfkit/models/blinn_phong_lobe.h"
#include "brdfkit/models/he_torrance.h"
#include "brdfkit/models/lafortune.h"
#include "brdfkit/models/lambert.h"
#include "brdfkit/models/lobe_sum.h"
#include "brdfkit/models/low_smooth.h"
#include "brdfkit/models/low_microfacet.h"
#include "brdfkit/models/holzschuch_pacanowski.h"
#include "brdfkit/models/poulin_fournier.h"
#include "brdfkit/models/published_fits.h"
#include "brdfkit/models/ward.h"
#include "brdfkit/models/ward_duer.h"
#include "brdfkit/ndf/beckmann_anisotropic.h"
#include "brdfkit/ndf/ggx_anisotropic.h"
#include "brdfkit/models/disney_principled.h"
#include "brdfkit/models/gltf_metallic_roughness.h"
#include "brdfkit/models/mitsuba_principled.h"
#include "brdfkit/models/mitsuba_roughconductor.h"
#include "brdfkit/models/pbrt_conductor.h"
#include "brdfkit/models/pbrt_diffuse.h"
#include "brdfkit/models/pbrt_mix.h"
#include "brdfkit/models/model.h"

namespace brdfkit {

namespace {
template <class M> const Model* instance() {
  static const ModelAdapter<M> m;
  return &m;
}
}  // namespace

const Registry<const Model*>& model_registry() {
  static const Registry<const Model*> registry = [] {
    Registry<const Model*> r("model");
    auto add = [&](const Model* m) { r.add(std::string(m->name()), m); };
    add(instance<Lambert>());
    for (const Model* m : cook_torrance_models()) add(m);
    add(instance<CookTorranceAnisotropic<BeckmannAnisotropic>>());
    add(instance<CookTorranceAnisotropic<GgxAnisotropic>>());
    add(instance<PoulinFournier>());
    for (const Model* m : {instance<Ward>(), instance<WardAniso>(), instance<WardDuer>(), instance<BlinnPhongLobe>(),
                           instance<Lafortune>(), instance<Lafortune2>(), instance<AshikhminShirley>(),
                           instance<AshikhminShirleyDielectric>(), instance<AshikhminShirleyNgan>(),
                           instance<HeTorrance>(), instance<LowSmooth>(),
                           instance<LowSmooth2>(), low_microfacet_model(), holzschuch_pacanowski_model(),
                           low_cook_torrance_model(), bagher_sgd_model()})
      add(m);
    // The renderers' own BSDFs (models/<renderer>_*.h), each as its renderer evaluates it.
    for (const Model* m : {instance<GltfMetallicRoughness>(), instance<MitsubaRoughConductorBeckmann>(),
                           instance<MitsubaRoughConductorGgx>(), instance<MitsubaPrincipled>(), instance<PbrtConductor>(),
                           instance<PbrtConductorReflectance>(), instance<PbrtDiffuse>(),
                           instance<PbrtMixDiffuseConductor>(), instance<DisneyPrincipled>()})
      add(m);
    return r;
  }();
  return registry;
}

std::span<const Model* const> all_models() { return model_registry().values(); }

const Model& model_by_name(std::string_view name) {
  // Sums "a+b+…" (models/lobe_sum.h) are built on first use and live as long as the program, as
  // the registered models do, so a Brdf may keep a pointer to one.
  if (LobeSum::is_sum_name(name)) {
    static std::mutex mutex;
    static std::map<std::string, std::unique_ptr<LobeSum>, std::less<>> sums;
    const std::lock_guard lock(mutex);
    if (auto it = sums.find(name); it != sums.end()) return *it->second;
    auto sum = LobeSum::from_name(name);
    const Model& m = *sum;
    sums.emplace(std::string(name), std::move(sum));
    return m;
  }
  if (const Model* const* m = model_registry().find(name)) return **m;
  throw model_registry().unknown(name, " (and sums of them joined by '+')");
}

}  // namespace brdfkit
