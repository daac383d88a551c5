#pragma once
// Parameter sets of `low-microfacet` (seed 003 Eq. 15) and `holzschuch-pacanowski` (seed 004
// Eq. 24–27) shared by this folder's tests: typical, sharp, broad and the C ≈ 1 case of Löw's
// sampler (its near-1 fallback).
#include <string>
#include <utility>
#include <vector>

#include "brdfkit/models/model.h"

namespace brdfkit::test {

struct LowHpCase {
  std::string model;
  std::string label;
  std::vector<std::pair<std::string, double>> values;  // set on every channel
};

inline ParamValues values_of(const Model& m, const LowHpCase& c) {
  ParamValues v = ParamValues::defaults(m.params());
  for (const auto& [name, value] : c.values) v.set(m.params(), name, value);
  return v;
}

// Shapes χ² (adaptive quadrature per cell) resolves quickly.
inline std::vector<LowHpCase> low_hp_moderate_cases() {
  return {
      {"low-microfacet", "B100_C1", {{"kd", 0.2}, {"A", 2.0}, {"B", 100}, {"C", 1.0}, {"eta", 1.5}}},
      {"low-microfacet", "B2000_C1.5", {{"kd", 0.1}, {"A", 5.0}, {"B", 2000}, {"C", 1.5}, {"eta", 2.0}}},
      {"low-microfacet", "B30_C0.5", {{"kd", 0.05}, {"A", 0.5}, {"B", 30}, {"C", 0.5}, {"eta", 1.3}}},
      // |(1 − C) ln(1 + B)| < 1e-9: the C = 1 branch of Eq. 25 (seed 003's near-1 fallback).
      {"low-microfacet", "B500_C1+1e-12", {{"kd", 0.1}, {"A", 3.0}, {"B", 500}, {"C", 1.0 + 1e-12}, {"eta", 1.6}}},
      {"holzschuch-pacanowski", "defaults", {}},
      {"holzschuch-pacanowski", "s0.05_p0.4_a0.5",
       {{"kd", 0.05}, {"ks", 0.6}, {"kw", 0.02}, {"sigma", 0.05}, {"p", 0.4}, {"a", 0.5}, {"F0", 0.5}}},
      {"holzschuch-pacanowski", "s0.3_p1.5_a2",
       {{"kd", 0.1}, {"ks", 1.0}, {"kw", 0.01}, {"sigma", 0.3}, {"p", 1.5}, {"a", 2.0}, {"F0", 0.9}}},
  };
}

// Sharp shapes (published-fit territory) for the checks that need no cell quadrature.
inline std::vector<LowHpCase> low_hp_sharp_cases() {
  return {
      // aluminium's published E2 fit (R), A divided by π (published_fits.cpp).
      {"low-microfacet", "aluminium", {{"kd", 0.0}, {"A", 1137.95678 / 3.14159265358979}, {"B", 218716.59754},
                                       {"C", 1.092006}, {"eta", 6.28268}}},
      {"low-microfacet", "B1e7_C0.1", {{"kd", 0.1}, {"A", 10.0}, {"B", 1e7}, {"C", 0.1}, {"eta", 50}}},
      // nickel's a, σ, p of seed 004 Fig. 12(a).
      {"holzschuch-pacanowski", "nickel_fig12", {{"kd", 0.01}, {"ks", 0.7}, {"kw", 0.05}, {"sigma", 0.027},
                                                 {"p", 0.51}, {"a", 0.91}, {"F0", 0.6}}},
      {"holzschuch-pacanowski", "s0.001_a0.05", {{"kd", 0.1}, {"ks", 1.0}, {"kw", 0.005}, {"sigma", 0.001},
                                                 {"p", 0.3}, {"a", 0.05}, {"F0", 0.04}}},
  };
}

}  // namespace brdfkit::test
