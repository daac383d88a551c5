// An evaluation the CLI fuzz target reached (fuzz/fuzz_cli_options.cpp): an SGD model whose Smith
// Λ scan holds only values below ~5e-304. The panel cut 1e-20·gmax underflowed to 0, the log of
// two zero edges was −∞ − (−∞) = NaN and its cast to int undefined; UBSan reports it in the
// sanitized build of these tests (fuzz/CMakeLists.txt), a plain build computes the same numbers.
#include <gtest/gtest.h>

#include <cmath>

#include "brdfkit/shadowing/smith_integral.h"

namespace brdfkit {
namespace {

// g is 1e-310 (subnormal) on the panels w in [−2, 0] and exactly 0 elsewhere: gmax·1e-20 is 0.
TEST(SmithIntegralFuzzRegressions, ScanOfSubnormalValuesIntegratesToAtMostItsBound) {
  auto g = [](double w) { return (w >= -2.0 && w <= 0.0) ? 1e-310 : 0.0; };
  const double v = smith_detail::integrate_log_panels<double>(g, -10.0, 10.0);
  EXPECT_TRUE(std::isfinite(v));
  EXPECT_GE(v, 0.0);
  EXPECT_LE(v, 1e-310 * 2.5);  // the integrand's mass, with a panel's slack
}

}  // namespace
}  // namespace brdfkit
