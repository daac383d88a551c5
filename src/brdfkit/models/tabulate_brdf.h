#pragma once
// A model with parameters as a MERL-format table (measured/merl_tabulate.h: every cell filled by
// index at its centre), refusing what the format cannot hold: a value that is NaN or infinite, and
// a negative value, which a MERL file would read as a cell that was not measured.
#include <cstddef>

#include "brdfkit/measured/merl.h"
#include "brdfkit/models/model.h"

namespace brdfkit {

struct BrdfTable {
  merl::Table table;
  std::size_t clamped = 0;  // cells stored as 0 in place of a negative value (clamp_negative)
  Rgb max_rho = Rgb::Zero();  // per channel, over the cells written
};

// InputError naming the model and the number of cells when the BRDF is not finite in any cell
// above the horizon, or negative in any (unless clamp_negative: then max(0, ρ) is stored).
BrdfTable tabulate_brdf(const Brdf& brdf, bool clamp_negative);

}  // namespace brdfkit
