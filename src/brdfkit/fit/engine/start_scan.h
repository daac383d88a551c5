#pragma once
// How start 0 of a fit is chosen. From the table's defaults alone a local solver can end
// in a poorer basin than a scan finds (Cornell, ngan, defaults → scanned: he on acryl_blue 0.2007 →
// 0.1701, ashikhmin-shirley-dielectric 0.3386 → 0.2833, ward on garnet_red 0.3732 → 0.3663). So
// start 0 is the best point of a deterministic scan of the solver's box, evaluated with the
// colours solved linearly (variable projection), which makes each point one pass over a
// subsample of the domain:
//   - every fitted parameter gets a 1-D grid of cell centres inside its bounds (never on them),
//     log-spaced where the bounds span ≥ kLogSpan (widths, exponents, sharpness: their effect is
//     multiplicative) and linear otherwise (shapes like SGD's p, Lafortune's C, Fresnel F0);
//   - coordinate sweeps: each parameter in table order is scanned with the others at the best
//     point so far, then the next parameter; a per-channel parameter's three variables first
//     move together, then each alone, since channels may need different basins (vch_golden_yellow's
//     He: η 2.23 in green, 0.058 in red, ngan 0.2017; its three η moving together only: 0.2348);
//     sweeps repeat (at most `sweeps`) while they improve the cost;
//   - the defaults are the first point, so the scan never returns a worse start than them.
// The local solver then starts from that point (the coarse-to-fine levels of fit_model).
#include <cstddef>
#include <functional>
#include <vector>

#include "brdfkit/core/param.h"

namespace brdfkit::fit {

// A parameter whose bounds span at least this ratio (lower > 0), or whose lower bound is 0 and
// upper at least this, is scanned on a log scale.
inline constexpr double kLogSpan = 50;

// The grid of one parameter (see above); empty when a bound is not finite or the bounds are equal.
std::vector<double> scan_grid(const ParamSpec& s);

// The sample stride for the scan: every s-th sample of the domain, keeping about 20 000 of them
// (enough to place a lobe; the solver's levels then refine on the whole domain).
std::size_t scan_stride(std::size_t samples);

struct StartScan {
  std::vector<double> x;  // the best point (solver variables)
  double cost = 0;        // its cost (+inf when no point was finite)
  int points = 0;         // points evaluated, the start included
};

// var_param[v]: the ParamTable index of solver variable v (variables of one parameter move
// together). cost(x): the objective at x, +inf where the model is not finite. Deterministic.
StartScan scan_start(const ParamTable& table, const std::vector<int>& var_param, const std::vector<double>& start,
                     const std::function<double(const std::vector<double>&)>& cost, int sweeps = 2);

}  // namespace brdfkit::fit
