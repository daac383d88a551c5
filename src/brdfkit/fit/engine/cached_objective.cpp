#include "brdfkit/fit/engine/cached_objective.h"

#include <algorithm>
#include <cmath>

namespace brdfkit::fit {

bool CachedObjective::evaluate(const double* x, bool derivatives, ObjectiveValue& out, ParamValues& values) {
  if (last_.valid && (last_.derivatives || !derivatives) && std::equal(last_.x.begin(), last_.x.end(), x)) {
    out = last_.value;
    values = last_.values;
    return true;
  }
  if (!inner_->evaluate(x, derivatives, out, values) || !std::isfinite(out.cost)) return false;
  if (derivatives && (!out.gradient.allFinite() || !out.jtj.allFinite())) return false;
  last_ = {true, derivatives, std::vector<double>(x, x + n_), out, values};
  if (out.cost < best_.cost) best_ = {out.cost, last_.x};
  return true;
}

}  // namespace brdfkit::fit
