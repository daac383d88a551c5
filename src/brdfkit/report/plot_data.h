#pragma once
// The data behind a material's plots, as JSON for the report's charts (values are linear-sRGB
// luminance Y of ρ, DESIGN.md §2): incidence-plane slices ρ cos θo at θi = 0°, 30°, 60°, 75° (seed
// 002 Fig. 4, seed 003 Fig. 12), (θh, θd) maps of data, fit and their ratio, and the directional
// albedo a(θi) of data and fits.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdfkit/measured/measured_brdf.h"
#include "brdfkit/models/model.h"

namespace brdfkit::report {

// Whether the data answer ρ(wi, wo) anywhere (tabulated formats) or only hold samples (Cornell).
bool answers_eval(const MeasuredBrdf& data);

struct NamedBrdf {
  std::string name;
  Brdf brdf;
};

// {"theta_i_deg": [...], "slices": [{"theta_i_deg", "data": [[θo, y]…], "data_kind": "curve"|
// "samples"|"none", "fits": {name: [[θo, y]…]}}]}. θo is signed: positive on the mirror side.
// Tabulated data are evaluated on a 1° grid; scattered data (Cornell) give their samples within
// 1° of θi and 4° of the incidence plane.
nlohmann::json incidence_slices(const MeasuredBrdf& data, const std::vector<NamedBrdf>& fits);

// Means over the data's valid samples (θi, θo ≤ 85°) binned in 2° cells of (θh, θd), of the data
// and of `fit` at the same direction pairs: {"bin_deg": 2, "data": [[iθd, iθh, log10 Y]…],
// "fit": […], "log2_ratio": [[iθd, iθh, log2(data/fit)]…]} (cells without samples or with a
// non-positive mean are left out). At most `max_samples` samples, evenly strided.
nlohmann::json half_diff_maps(const MeasuredBrdf& data, const NamedBrdf& fit, size_t max_samples = 200000);

// {"theta_i_deg": [0, 5, …, 85], "data": [y or null…], "fits": {name: [y…]}}.
nlohmann::json albedo_curves(const MeasuredBrdf& data, const std::vector<NamedBrdf>& fits);

}  // namespace brdfkit::report
