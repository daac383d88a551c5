#pragma once
// Forward differences of the model with respect to the solver's variables: the shape parameters
// enter the models through special functions, tables and series that have no cheap derivative in
// doubles, and one extra sweep per variable is what a Jacobian costs either way.
#include <vector>

#include "brdfkit/fit/engine/solver_variables.h"

namespace brdfkit::fit {

// Step of variable v at x: 1e-6 relative (absolute below 1e-3), taken backwards where a forward
// step would leave the upper bound.
double difference_step(const ParamSpec& s, double x);

// The points x + h_v e_v, one per variable, as parameter values over `base`; their steps in h.
std::vector<ParamValues> shifted_points(const SolverVariables& vars, const double* x, const ParamValues& base,
                                        std::vector<double>& h);

}  // namespace brdfkit::fit
