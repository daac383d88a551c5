#pragma once
// Parameter sets the model tests run every registered model at: the defaults, and every lobe-shape
// (non-linear) parameter moved 35 % of the way towards each bound (geometrically, by at most a
// factor 3, where the move stays positive: a width of 0.2 in [1e-3, 2] becomes 0.45 and 0.067).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "brdfkit/models/model.h"

namespace brdfkit::test {

struct NamedParams {
  std::string label;
  ParamValues values;
};

inline std::vector<NamedParams> model_param_sets(const Model& m, double fraction = 0.35) {
  const ParamTable& t = m.params();
  std::vector<NamedParams> sets{{"defaults", ParamValues::defaults(t)}};
  for (int dir : {+1, -1}) {
    ParamValues v = ParamValues::defaults(t);
    for (size_t i = 0; i < t.size(); ++i) {
      const ParamSpec& s = t[i];
      if (s.linear) continue;
      const double target = dir > 0 ? s.upper : s.lower;
      double x;
      // Geometric, at most a factor 3, so huge ranges stay testable (an exponent N in [0, 1e6]
      // moves to 150, not 3.5e5, a lobe no quadrature of the pdf resolves).
      if (s.def > 0 && (dir > 0 || s.lower > 0))
        x = s.def * std::clamp(std::pow(target / s.def, fraction), 1.0 / 3.0, 3.0);
      else
        x = s.def + (target - s.def) * fraction;
      for (auto& ch : v.values) ch[i] = x;
    }
    sets.push_back({dir > 0 ? "shape towards upper bounds" : "shape towards lower bounds", v});
  }
  return sets;
}

}  // namespace brdfkit::test
