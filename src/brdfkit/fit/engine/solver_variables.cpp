#include "brdfkit/fit/engine/solver_variables.h"

#include <algorithm>

namespace brdfkit::fit {

SolverVariables::SolverVariables(const ParamTable& table, const std::vector<bool>& solved_inside) : table_(table) {
  for (size_t p = 0; p < table.size(); ++p) {
    const ParamSpec& s = table[p];
    if (!(s.upper > s.lower) || solved_inside[p]) continue;
    if (s.scope == Scope::Shared) vars_.push_back({int(p), -1});
    else
      for (int c = 0; c < 3; ++c) vars_.push_back({int(p), c});
  }
}

std::vector<int> SolverVariables::params() const {
  std::vector<int> out;
  for (const SolverVariable& v : vars_) out.push_back(v.param);
  return out;
}

void SolverVariables::write(const double* x, ParamValues& pv) const {
  for (size_t v = 0; v < vars_.size(); ++v)
    for (int c = 0; c < 3; ++c)
      if (vars_[v].affects(c)) pv.values[size_t(c)][size_t(vars_[v].param)] = x[v];
}

void SolverVariables::read(const ParamValues& pv, double* x) const {
  for (size_t v = 0; v < vars_.size(); ++v) x[v] = pv.values[size_t(std::max(0, vars_[v].channel))][size_t(vars_[v].param)];
}

}  // namespace brdfkit::fit
