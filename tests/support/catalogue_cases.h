#pragma once
// Parameter sets of the classic (seed 002) and Löw (seed 003) models exercised by the
// catalogue tests: typical, sharp and wide shapes, coloured channels.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "brdfkit/models/model.h"

namespace brdfkit::test {

struct ModelCase {
  std::string model;
  std::string label;
  std::vector<std::pair<std::string, double>> values;  // set on every channel
};

inline ParamValues values_of(const Model& m, const ModelCase& c) {
  ParamValues v = ParamValues::defaults(m.params());
  for (const auto& [name, value] : c.values) v.set(m.params(), name, value);
  return v;
}

// Moderate shapes: what χ² (adaptive quadrature per cell) can resolve quickly.
inline std::vector<ModelCase> moderate_cases() {
  return {
      {"ward", "a0.1", {{"kd", 0.3}, {"ks", 0.2}, {"alpha", 0.1}}},
      {"ward", "a0.4", {{"kd", 0.1}, {"ks", 0.5}, {"alpha", 0.4}}},
      {"ward-aniso", "ax0.08_ay0.3", {{"kd", 0.2}, {"ks", 0.4}, {"alpha_x", 0.08}, {"alpha_y", 0.3}}},
      {"cook-torrance-ggx-aniso", "ax0.1_ay0.35_phi0.7",
       {{"kd", 0.2}, {"ks", 0.6}, {"alpha_x", 0.1}, {"alpha_y", 0.35}, {"phi_t", 0.7}, {"F0", 0.3}}},
      {"cook-torrance-beckmann-aniso", "ax0.3_ay0.12_phi-1",
       {{"kd", 0.1}, {"ks", 0.8}, {"alpha_x", 0.3}, {"alpha_y", 0.12}, {"phi_t", -1.0}, {"F0", 0.9}}},
      {"poulin-fournier", "n40_d0.3_h0.7_phi0.4",
       {{"kd", 0.2}, {"ks", 0.7}, {"n", 40}, {"d", 0.3}, {"h", 0.7}, {"phi_t", 0.4}}},
      {"ward-duer", "a0.15", {{"kd", 0.2}, {"ks", 0.3}, {"alpha", 0.15}}},
      {"blinn-phong", "N40", {{"kd", 0.3}, {"ks", 0.4}, {"N", 40}}},
      {"blinn-phong", "N3.5", {{"kd", 0.1}, {"ks", 0.6}, {"N", 3.5}}},
      {"lafortune", "mirror_N25", {{"kd", 0.2}, {"ks", 0.5}, {"Cxy", -1.0}, {"Cz", 0.95}, {"N", 25}}},
      // |Cxy| = |Cz| is a kink of max(|Cxy|, |Cz|): the Jet takes one side, so not in the Jet cases.
      {"lafortune", "tie_N25", {{"kd", 0.2}, {"ks", 0.5}, {"Cxy", -1.0}, {"Cz", 1.0}, {"N", 25}}},
      {"lafortune", "offspec_N7.3", {{"kd", 0.1}, {"ks", 0.6}, {"Cxy", -0.8}, {"Cz", 0.6}, {"N", 7.3}}},
      {"lafortune-2", "two",
       {{"kd", 0.1}, {"ks1", 0.4}, {"Cxy1", -1.0}, {"Cz1", 0.9}, {"N1", 60}, {"ks2", 0.3}, {"Cxy2", -0.5},
        {"Cz2", 1.0}, {"N2", 4.5}}},
      {"ashikhmin-shirley", "N80", {{"kd", 0.3}, {"Rs", 0.05}, {"N", 80}}},
      {"ashikhmin-shirley", "N8_metal", {{"kd", 0.02}, {"Rs", 0.8}, {"N", 8}}},
      {"ashikhmin-shirley-dielectric", "N120", {{"kd", 0.2}, {"ks", 1.0}, {"N", 120}, {"eta", 1.5}}},
      {"low-smooth", "B300_C1", {{"kd", 0.2}, {"A", 5.0}, {"B", 300}, {"C", 1.0}, {"eta", 1.5}}},
      {"low-smooth", "B50_C0.6", {{"kd", 0.1}, {"A", 1.0}, {"B", 50}, {"C", 0.6}, {"eta", 2.0}}},
      {"low-smooth", "B800_C1.8", {{"kd", 0.1}, {"A", 20.0}, {"B", 800}, {"C", 1.8}, {"eta", 1.3}}},
      {"low-smooth-2", "two",
       {{"kd", 0.1}, {"A1", 0.3}, {"B1", 20}, {"C1", 0.8}, {"A2", 10.0}, {"B2", 500}, {"C2", 1.2}, {"eta", 1.6}}},
  };
}

// Sharp shapes (published-fit territory) for the checks that need no cell quadrature.
inline std::vector<ModelCase> sharp_cases() {
  return {
      {"ward", "a0.005", {{"kd", 0.1}, {"ks", 0.5}, {"alpha", 0.005}}},
      {"ward-duer", "a0.01", {{"kd", 0.1}, {"ks", 0.5}, {"alpha", 0.01}}},
      {"blinn-phong", "N5000", {{"kd", 0.1}, {"ks", 0.5}, {"N", 5000}}},
      {"poulin-fournier", "ngan2005_brushed_aluminium",
       {{"kd", 0.1}, {"ks", 0.5}, {"n", 3000}, {"d", 0.18}, {"h", 0.5}, {"phi_t", 0.0}}},
      {"lafortune", "N2000", {{"kd", 0.1}, {"ks", 0.5}, {"Cxy", -0.99}, {"Cz", 1.0}, {"N", 2000}}},
      {"ashikhmin-shirley-dielectric", "N6e5", {{"kd", 0.1}, {"ks", 1.0}, {"N", 621578}, {"eta", 2.0}}},
      {"low-smooth", "B4.5e6", {{"kd", 0.01}, {"A", 2000.0}, {"B", 4.5e6}, {"C", 0.7}, {"eta", 1.6}}},
  };
}

}  // namespace brdfkit::test
