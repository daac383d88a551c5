#pragma once
// The Fresnel term a measured BRDF implies, given a fitted microfacet model (seed 000 §4.4 Eq. 10):
//   F(θd) = (m − kd/π) · 4 cosθi cosθo / (ks D(θh) G1(θi) G1(θo)),
// Eq. 10 with the ρs/π of seed 000 Eq. 1 written as ks/4 (models/cook_torrance.h). Taken on the
// θh = 0 slice m_d(θd) = m(i, mirror(i)) as seed 000 §5.2 does (θi = θo = θd, D at its peak). G1
// is the Smith masking of the model's D (analysis/projected_area_masking.h), whatever masking the
// model itself uses. The model's own curve comes from the same formula applied to its values, so
// both curves carry the same assumptions. Seed 000 discards θd > 70° (saturated sensor).
#include <vector>

#include "brdfkit/core/vec.h"
#include "brdfkit/measured/measured_brdf.h"
#include "brdfkit/models/model.h"

namespace brdfkit::analysis {

struct FresnelCurve {
  std::vector<double> theta_d;   // radians
  std::vector<Rgb> data;         // extracted from the measurement (NaN-free; missing → has_data false)
  std::vector<bool> has_data;
  std::vector<Rgb> model;        // the same extraction applied to the model's values
  std::vector<bool> reliable;    // θd ≤ 70° (seed 000 §4.4)
};

struct FresnelOptions {
  int nodes = 90;  // θd = (j+½)/n · π/2 (MERL's θd cell centres)
};

// InputError when the model has no microfacet distribution or no kd/ks parameters.
FresnelCurve extract_fresnel(const MeasuredBrdf& data, const Model& model, const ParamValues& values,
                             const FresnelOptions& opt = {});

}  // namespace brdfkit::analysis
