#include "brdfkit/fit/engine/finite_difference.h"

#include <algorithm>
#include <cmath>

namespace brdfkit::fit {

double difference_step(const ParamSpec& s, double x) {
  double h = 1e-6 * std::max(std::abs(x), 1e-3);
  if (x + h > s.upper) h = -h;  // stay inside the bounds
  return h;
}

std::vector<ParamValues> shifted_points(const SolverVariables& vars, const double* x, const ParamValues& base,
                                        std::vector<double>& h) {
  const size_t nv = vars.size();
  h.assign(nv, 0.0);
  std::vector<ParamValues> points;
  for (size_t v = 0; v < nv; ++v) {
    std::vector<double> xh(x, x + nv);
    h[v] = difference_step(vars.spec(v), x[v]);
    xh[v] += h[v];
    ParamValues ph = base;
    vars.write(xh.data(), ph);
    points.push_back(std::move(ph));
  }
  return points;
}

}  // namespace brdfkit::fit
