#pragma once
// The solver's variables: the parameters a fit moves with the nonlinear solver. A Shared
// parameter is one variable for R, G and B; a per-channel one is three. Parameters fixed by their
// bounds (lower = upper) and those the objective solves itself (the colours of variable
// projection) are not variables. Everything else a fit knows about a variable is in its
// ParamSpec (bounds for the solver and the starts).
#include <cstddef>
#include <vector>

#include "brdfkit/core/param.h"

namespace brdfkit::fit {

struct SolverVariable {
  int param;    // index in the model's ParamTable
  int channel;  // −1: the same value in all three channels
  // Whether the variable moves channel (or basis class) q's parameters.
  bool affects(int q) const { return channel < 0 || channel == q; }
};

class SolverVariables {
 public:
  // solved_inside[p]: parameter p is solved by the objective (variable projection), not a variable.
  SolverVariables(const ParamTable& table, const std::vector<bool>& solved_inside);

  std::size_t size() const { return vars_.size(); }
  bool empty() const { return vars_.empty(); }
  const SolverVariable& operator[](std::size_t v) const { return vars_[v]; }
  auto begin() const { return vars_.begin(); }
  auto end() const { return vars_.end(); }
  const ParamSpec& spec(std::size_t v) const { return table_[std::size_t(vars_[v].param)]; }
  // The ParamTable index of every variable (variables of one parameter move together in scans).
  std::vector<int> params() const;

  // Writes x (one value per variable) into pv's channels.
  void write(const double* x, ParamValues& pv) const;
  // Reads the variables' values out of pv (a per-channel variable from its channel, a shared one
  // from channel 0).
  void read(const ParamValues& pv, double* x) const;

 private:
  const ParamTable& table_;
  std::vector<SolverVariable> vars_;
};

}  // namespace brdfkit::fit
