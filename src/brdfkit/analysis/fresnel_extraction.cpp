#include "brdfkit/analysis/fresnel_extraction.h"

#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "brdfkit/analysis/projected_area_masking.h"
#include "brdfkit/core/error.h"
#include "brdfkit/models/microfacet_model.h"

namespace brdfkit::analysis {

FresnelCurve extract_fresnel(const MeasuredBrdf& data, const Model& model, const ParamValues& values,
                             const FresnelOptions& opt) {
  const std::string where = "model '" + std::string(model.name()) + "'";
  const auto* view = dynamic_cast<const MicrofacetDistributionView*>(&model);
  const int kd = find_param(model.params(), "kd"), ks = find_param(model.params(), "ks");
  if (!view || kd < 0 || ks < 0)
    throw InputError(where, "Fresnel extraction (seed 000 Eq. 10) needs a microfacet model with kd, ks and a "
                            "distribution D (a cook-torrance-* model)");
  if (opt.nodes < 2 || opt.nodes > 100000) throw InputError("Fresnel extraction", "nodes must be in [2, 100000]");
  std::array<ProjectedAreaMasking, 3> masking;
  std::array<double, 3> d0{};
  for (int c = 0; c < 3; ++c) {
    const double* p = values.channel(c);
    masking[size_t(c)] = ProjectedAreaMasking([&](double cm) { return view->ndf(p, cm); }, {});
    d0[size_t(c)] = view->ndf(p, 1.0);
  }
  FresnelCurve out;
  bool any = false;
  for (int j = 0; j < opt.nodes; ++j) {
    const double td = (j + 0.5) / opt.nodes * kPi / 2, st = std::sin(td), ct = std::cos(td);
    const Vec3d wi(st, 0, ct), wo(-st, 0, ct);  // θh = 0: wo is the mirror of wi
    const auto m = data.eval(wi, wo);
    Rgb fd = Rgb::Zero(), fm = Rgb::Zero();
    for (int c = 0; c < 3; ++c) {
      const double* p = values.channel(c);
      const double g1 = masking[size_t(c)].g1(ct);
      const double denom = p[ks] * d0[size_t(c)] * g1 * g1;  // seed 000 Eq. 10
      auto extract = [&](double rho) { return denom > 0 ? (rho - p[kd] * kInvPi) * 4 * ct * ct / denom : 0.0; };
      fm[c] = extract(model.eval(p, c, wi, wo));
      if (m && m->allFinite()) fd[c] = extract((*m)[c]);
    }
    const bool has = m && m->allFinite() && fd.allFinite();
    any = any || has;
    out.theta_d.push_back(td);
    out.data.push_back(has ? fd : Rgb::Zero());
    out.has_data.push_back(has);
    out.model.push_back(fm.allFinite() ? fm : Rgb::Zero());
    out.reliable.push_back(td <= 70 * kPi / 180);
  }
  if (!any)
    throw InputError(data.path(), "no value on the theta_h = 0 slice (Fresnel extraction needs data that answer "
                                  "rho at the mirror configuration)");
  return out;
}

}  // namespace brdfkit::analysis
