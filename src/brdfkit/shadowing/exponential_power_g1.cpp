#include "brdfkit/shadowing/exponential_power_g1.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cmath>

namespace brdfkit {

double ExponentialPowerG1Table::g1_direct(double sigma_tan_theta, double p) {
  if (!(sigma_tan_theta > 0.0)) return 1.0;
  if (std::isinf(sigma_tan_theta)) return 0.0;
  const UnitDistribution<double> d(p);
  return 1.0 / (1.0 + smith_lambda_integral(d, sigma_tan_theta));
}

ExponentialPowerG1Table::ExponentialPowerG1Table() : g1_(size_t(kNa) * kNb) {
  // Isolated so that a caller running inside a TBB task cannot steal an outer task that waits on
  // this lazy initialisation (see smith_table.cpp).
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(0, kNa, [&](int ia) {
      const double a = 5 / kPMax + ia * (5 / kPMin - 5 / kPMax) / (kNa - 1);
      const double p = 5 / a;
      for (int ib = 0; ib < kNb; ++ib) {
        const double b = double(ib) / (kNb - 1);
        // b = exp(−z^(−1/20))  ⇔  z = (−log b)^(−20); b = 0 → z = 0, b = 1 → z = ∞.
        double g;
        if (ib == 0)
          g = 1.0;
        else if (ib == kNb - 1)
          g = 0.0;
        else
          g = g1_direct(std::pow(-std::log(b), -20.0), p);
        g1_[size_t(ia) * kNb + ib] = g;
      }
    });
  });
}

const ExponentialPowerG1Table& ExponentialPowerG1Table::instance() {
  static const ExponentialPowerG1Table table;
  return table;
}

}  // namespace brdfkit
