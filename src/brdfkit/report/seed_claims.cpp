#include "brdfkit/report/seed_claims.h"

#include <algorithm>
#include <optional>

namespace brdfkit::report {
namespace {

struct ClaimSpec {
  const char *claim, *source, *a, *b;
};

const ClaimSpec kClaims[] = {
    {"SGD fits better than Beckmann", "seed 000 (Bagher et al. 2012), Fig. 9", "cook-torrance-sgd", "cook-torrance-beckmann"},
    {"two lobes fit better than one", "seed 002 (Ngan et al. 2005), Fig. 5", "lafortune-2", "lafortune"},
    {"two lobes fit better than one", "seed 003 (Low et al. 2012), Eq. 34", "low-smooth-2", "low-smooth"},
    {"ABC (microfacet) fits better than Cook-Torrance", "seed 003 (Low et al. 2012), Fig. 10", "low-microfacet", "cook-torrance"},
    {"ABC (smooth surface) fits better than Cook-Torrance", "seed 003 (Low et al. 2012), Fig. 10", "low-smooth", "cook-torrance"},
};

const FitResult* find_fit(const MaterialResult& m, const std::string& model) {
  for (const FitResult& f : m.fits)
    if (f.model == model) return &f;
  return nullptr;
}

}  // namespace

std::vector<ClaimResult> measure_seed_claims(const BatchResults& b) {
  std::vector<ClaimResult> out;
  for (const ClaimSpec& spec : kClaims) {
    ClaimResult r{spec.claim, spec.source, spec.a, spec.b, b.fit_metric};
    std::vector<double> ratios;
    for (const MaterialResult& m : b.materials) {
      const FitResult *fa = find_fit(m, spec.a), *fb = find_fit(m, spec.b);
      if (!fa || !fb) continue;
      const std::optional<double> ea = fa->metric(b.fit_metric), eb = fb->metric(b.fit_metric);
      if (!ea || !eb || *eb <= 0) continue;
      const double a = *ea, e = *eb;
      ++r.materials;
      r.a_better += a < e;
      ratios.push_back(a / e);
    }
    if (ratios.empty()) continue;
    std::sort(ratios.begin(), ratios.end());
    const size_t n = ratios.size();
    r.median_ratio = n % 2 ? ratios[n / 2] : (ratios[n / 2 - 1] + ratios[n / 2]) / 2;
    out.push_back(r);
  }
  return out;
}

nlohmann::json claims_json(const std::vector<ClaimResult>& claims) {
  nlohmann::json out = nlohmann::json::array();
  for (const ClaimResult& c : claims)
    out.push_back({{"claim", c.claim}, {"source", c.source}, {"model_a", c.model_a}, {"model_b", c.model_b},
                   {"metric", c.metric}, {"materials", c.materials}, {"a_better", c.a_better},
                   {"median_ratio", c.median_ratio}});
  return out;
}

}  // namespace brdfkit::report
