#pragma once
// Claims of the seed papers measured on a batch, where the batch holds both fits a claim compares
// (per material, the fitting metric's error of model A against model B):
//   seed 000 (Bagher 2012): the shifted gamma distribution fits better than Beckmann;
//   seed 002 (Ngan 2005) and seed 003 (Löw 2012): two lobes fit better than one;
//   seed 003 (Löw 2012): the ABC models fit better than Cook-Torrance.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdfkit/report/batch_results.h"

namespace brdfkit::report {

struct ClaimResult {
  std::string claim, source, model_a, model_b, metric;
  int materials = 0;   // materials with both fits
  int a_better = 0;    // of those, where A's error is lower
  double median_ratio = 0;  // median of error(A) / error(B)
};

// Every claim whose two models the batch has (each pair of the list that applies).
std::vector<ClaimResult> measure_seed_claims(const BatchResults& b);
nlohmann::json claims_json(const std::vector<ClaimResult>& claims);

}  // namespace brdfkit::report
