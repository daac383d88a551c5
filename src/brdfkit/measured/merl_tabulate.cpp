#include "brdfkit/measured/merl_tabulate.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>

#include "brdfkit/core/error.h"

namespace brdfkit::merl {

Table tabulate(const TabulatedBrdf& rho) {
  Table table;  // every cell −1 (not measured) until filled
  std::atomic<size_t> first_bad{kCellCount};
  tbb::parallel_for(0, kResThetaH, [&](int ih) {
    for (int id = 0; id < kResThetaD; ++id)
      for (int ip = 0; ip < kResPhiD; ++ip) {
        const Cell c{ih, id, ip};
        Vec3d wi, wo;
        if (!cell_directions(c, wi, wo)) continue;
        const Rgb v = rho(wi, wo);
        const size_t k = cell_offset(c);
        if (!v.allFinite()) {
          // Keep the lowest offset so the message does not depend on the schedule.
          size_t cur = first_bad.load();
          while (k < cur && !first_bad.compare_exchange_weak(cur, k)) {
          }
          continue;
        }
        // Stored value = ρ / scale (inverse of the reader's scaling, DESIGN.md §2).
        table.set_raw(k, v[0] / kScale[0], v[1] / kScale[1], v[2] / kScale[2]);
      }
  });
  if (const size_t k = first_bad.load(); k < kCellCount) {
    const Cell c = cell_at(k);
    throw InputError("tabulate", fmt::format("the BRDF is not finite at cell θh {} θd {} φd {}", c.theta_h,
                                             c.theta_d, c.phi_d));
  }
  return table;
}

}  // namespace brdfkit::merl
