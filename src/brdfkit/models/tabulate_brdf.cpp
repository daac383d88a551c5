#include "brdfkit/models/tabulate_brdf.h"

#include <fmt/format.h>

#include <atomic>

#include "brdfkit/core/error.h"
#include "brdfkit/measured/merl_tabulate.h"

namespace brdfkit {

BrdfTable tabulate_brdf(const Brdf& brdf, bool clamp_negative) {
  std::atomic<size_t> non_finite{0}, negative{0};
  BrdfTable out{merl::tabulate([&](const Vec3d& wi, const Vec3d& wo) {
    Rgb v = brdf.eval(wi, wo);
    if (!v.allFinite()) {
      ++non_finite;
      return Rgb(Rgb::Zero());  // counted; refused below
    }
    if ((v.array() < 0).any()) {
      ++negative;
      v = v.cwiseMax(0.0);
    }
    return v;
  })};
  const std::string what = fmt::format("model '{}'", brdf.model().name());
  if (non_finite > 0)
    throw InputError(what, fmt::format("the BRDF is NaN or infinite in {} of the {} cells above the horizon; "
                                       "nothing written",
                                       non_finite.load(), out.table.valid_count()));
  if (negative > 0 && !clamp_negative)
    throw InputError(what, fmt::format("the BRDF is negative in {} cells (they would read as 'not measured'); "
                                       "nothing written (--clamp-negative stores max(0, rho) instead)",
                                       negative.load()));
  out.clamped = negative;
  for (size_t k = 0; k < merl::kCellCount; ++k)
    if (out.table.valid(k)) out.max_rho = out.max_rho.cwiseMax(out.table.value(k));
  return out;
}

}  // namespace brdfkit
