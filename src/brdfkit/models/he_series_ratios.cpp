// The term ratios of He's series walk (he_series.h) as a vector kernel: He et al. 1991 Eq. 78's
// t_{j+1}/t_j, with glibc's vector exp.
#include "brdfkit/core/vector_kernel.h"
#include "brdfkit/models/he_series.h"

namespace brdfkit::he_detail {

BRDFKIT_VECTOR_KERNEL void term_ratios(double g, double c, int j0, int step, double* __restrict r) {
  for (int k = 0; k < kRatioBlock; ++k) {
    const int jk = j0 + step * k;
    const double j = jk > 1 ? jk : 1, j1 = j + 1;
    r[k] = g * j / (j1 * j1) * exp(c / (j * j1));
  }
}

}  // namespace brdfkit::he_detail
