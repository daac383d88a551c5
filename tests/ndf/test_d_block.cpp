// D_block (ndf/d_block.h), the vector-math D of the batch loops, against the scalar D: within 1e-12
// relative at every cosine of (0, 1] over each parameter's range, 0 at and below the horizon, and
// each value independent of where it lies in the block.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "brdfkit/ndf/d_block.h"
#include "support/all_ndfs.h"

namespace brdfkit {
namespace {

// Cosines of one block: θ uniform over [0, π/2] with the ends, a grazing tail and the horizon.
std::vector<double> block_cosines() {
  std::vector<double> c(kDBlock);
  for (std::size_t k = 0; k < kDBlock; ++k) c[k] = std::cos(double(k) / double(kDBlock - 1) * kPi / 2);
  c[kDBlock - 1] = 0.0;
  c[kDBlock - 2] = -0.3;
  c[kDBlock - 3] = 1e-9;
  c[1] = 1.0 - 1e-16;
  return c;
}

// The largest relative difference between D_block and D over the block at parameters p; values under
// 1e-280 (where exp's results are subnormal) compare absolutely.
template <template <class> class Ndf> double worst_relative(const std::vector<double>& p) {
  const Ndf<double> ndf(p.data());
  const std::vector<double> c = block_cosines();
  std::vector<double> got(kDBlock);
  ndf.D_block(c.data(), got.data());
  double worst = 0;
  for (std::size_t k = 0; k < kDBlock; ++k) {
    const double want = ndf.D(c[k]);
    EXPECT_TRUE(std::isfinite(got[k])) << Ndf<double>::kName << " c = " << c[k];
    if (!(c[k] > 0)) {
      EXPECT_EQ(got[k], 0.0) << Ndf<double>::kName << " c = " << c[k];
    }
    worst = std::max(worst, std::abs(got[k] - want) / std::max(std::abs(want), 1e-280));
  }
  return worst;
}

// A rotated block gives each cosine the same value, bit for bit.
template <template <class> class Ndf> void expect_position_free(const std::vector<double>& p) {
  const Ndf<double> ndf(p.data());
  std::vector<double> c = block_cosines(), a(kDBlock), b(kDBlock);
  ndf.D_block(c.data(), a.data());
  std::rotate(c.begin(), c.begin() + 37, c.end());
  ndf.D_block(c.data(), b.data());
  std::rotate(a.begin(), a.begin() + 37, a.end());
  for (std::size_t k = 0; k < kDBlock; ++k) ASSERT_EQ(a[k], b[k]) << Ndf<double>::kName << " position " << k;
}

// Relative bound: glibc's libmvec functions are within 4 ulp; an exp of an argument near −700 turns
// the argument's own few-ulp error into up to 700 × that, hence 1e-12 rather than a few 1e-16.
constexpr double kBound = 1e-12;

template <template <class> class Ndf> void expect_close(const std::vector<std::vector<double>>& params) {
  double worst = 0;
  for (const auto& p : params) {
    worst = std::max(worst, worst_relative<Ndf>(p));
    expect_position_free<Ndf>(p);
  }
  std::printf("%s: D_block within %.3g relative of D over %zu parameter sets\n",
              std::string(Ndf<double>::kName).c_str(), worst, params.size());
  EXPECT_LE(worst, kBound) << Ndf<double>::kName;
}

TEST(DBlock, BlinnPhongMatchesD) { expect_close<BlinnPhong>({{0.0}, {1.0}, {30.0}, {1e3}, {1e6}}); }
TEST(DBlock, BeckmannMatchesD) { expect_close<Beckmann>({{1e-3}, {0.05}, {0.3}, {2.0}}); }
TEST(DBlock, ExponentialMatchesD) { expect_close<Exponential>({{1e-3}, {0.05}, {0.3}, {2.0}}); }
TEST(DBlock, GaussianMatchesD) { expect_close<Gaussian>({{1e-3}, {0.02}, {0.2}, {0.7}, {1.5}}); }
TEST(DBlock, GtrMatchesD) {
  expect_close<Gtr>({{1e-3, 0.1}, {0.05, 1.0}, {0.2, 2.0}, {0.3, 2.7}, {0.9, 10.0}, {2.0, 0.5}});
}
TEST(DBlock, SgdMatchesD) { expect_close<Sgd>({{1e-6, 0.0}, {0.01, 0.6}, {0.05, 1.0}, {0.3, 1.5}, {2.0, 1.95}}); }
TEST(DBlock, ExponentialPowerMatchesD) {
  expect_close<ExponentialPower>({{1e-4, 0.05}, {0.02, 0.5}, {0.1, 1.0}, {0.4, 3.0}, {2.0, 10.0}});
}

}  // namespace
}  // namespace brdfkit
