// The solver's view of a metric domain (fit/engine/sample_blocks.h) and the inner products it takes
// over it (fit/engine/weighted_dots.h):
//   - blocks at a stride hold every s-th sample of each chunk, in chunk order, with the weight
//     (scale · √w · f)² · s, whether a block is one chunk (s = 1) or gathers several (s > 1);
//   - weighted_dots gives each term the sum weighted_dot's four interleaved partial sums give, to
//     the bit, for any number of terms and any block length (remainders included).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "brdfkit/fit/engine/sample_blocks.h"
#include "brdfkit/fit/engine/weighted_dots.h"
#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/measured/merl.h"
#include "brdfkit/measured/merl_brdf.h"

namespace brdfkit::fit {
namespace {

// Σ w² x y in four partial sums, lane l over k ≡ l (mod 4), the remainder into lane 0, then
// (s0 + s1) + (s2 + s3): the order weighted_dots documents.
double reference_dot(const std::vector<double>& w2, const std::vector<double>& x, const std::vector<double>& y) {
  double s[4] = {0, 0, 0, 0};
  const size_t n = w2.size();
  size_t k = 0;
  for (; k + 4 <= n; k += 4)
    for (size_t l = 0; l < 4; ++l) s[l] += w2[k + l] * x[k + l] * y[k + l];
  for (; k < n; ++k) s[0] += w2[k] * x[k] * y[k];
  return (s[0] + s[1]) + (s[2] + s[3]);
}

TEST(WeightedDots, EachTermIsTheFourLaneSumToTheBit) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  size_t checked = 0;
  for (size_t n : {0, 1, 3, 4, 5, 8, 1001, 2703}) {
    std::vector<double> w2(n);
    std::vector<std::vector<double>> cols(6, std::vector<double>(n));
    for (double& w : w2) w = std::abs(u(rng)) * 1e3;
    for (auto& c : cols)
      for (double& v : c) v = u(rng) * std::exp(8 * u(rng));  // magnitudes over seven decades
    for (size_t count : {1, 3, 4, 5, 9}) {
      std::vector<DotTerm> terms;
      std::vector<std::pair<size_t, size_t>> pairs;
      for (size_t t = 0; t < count; ++t) {
        const size_t a = t % cols.size(), b = (t * 5 + 1) % cols.size();
        terms.push_back({cols[a].data(), cols[b].data()});
        pairs.emplace_back(a, b);
      }
      std::vector<double> out(count);
      weighted_dots(n, w2.data(), terms, out.data());
      for (size_t t = 0; t < count; ++t) {
        const double want = reference_dot(w2, cols[pairs[t].first], cols[pairs[t].second]);
        EXPECT_EQ(out[t], want) << "n " << n << " terms " << count << " term " << t;
        EXPECT_EQ(weighted_dot(n, w2.data(), terms[t].x, terms[t].y), want) << "n " << n;
        ++checked;
      }
    }
  }
  std::printf("%zu weighted sums equal the four-lane sum to the bit\n", checked);
}

// Every s-th sample of every chunk, in order, against the blocks' concatenation.
void check_blocks(const Metric& metric, size_t s) {
  const std::vector<SampleBlock> blocks = sample_blocks(metric, s, BlockWeights::Squared);
  std::vector<double> want_x, want_mz, want_w2;
  MetricChunk scratch;
  for (size_t i = 0; i < metric.chunk_count(); ++i) {
    const MetricChunk& ch = metric.chunk(i, scratch);
    for (size_t k = 0; k < ch.size(); k += s) {
      want_x.push_back(ch.wi_x[k]);
      want_mz.push_back(ch.measured[2][k]);
      const double w = metric.scale() * ch.sqrt_weight[k] * std::sqrt(double(s)) * ch.factor[k];
      want_w2.push_back(w * w);
    }
  }
  size_t at = 0;
  for (size_t j = 0; j < blocks.size(); ++j) {
    const SampleBlock& b = blocks[j];
    if (s > 1 && j + 1 < blocks.size()) {
      EXPECT_GE(b.n, 2048u) << "stride " << s << " block " << j;
    }
    ASSERT_LE(at + b.n, want_x.size()) << "stride " << s;
    for (size_t k = 0; k < b.n; ++k, ++at) {
      ASSERT_EQ(b.d.wi_x[k], want_x[at]) << "stride " << s << " block " << j << " sample " << k;
      ASSERT_EQ(b.m[2][k], want_mz[at]) << "stride " << s << " block " << j << " sample " << k;
      ASSERT_EQ(b.w2[k], want_w2[at]) << "stride " << s << " block " << j << " sample " << k;
    }
  }
  EXPECT_EQ(at, want_x.size()) << "stride " << s;
  if (s == 1) {
    EXPECT_EQ(blocks.size(), metric.chunk_count());
  }
  std::printf("stride %zu: %zu samples in %zu blocks (%zu chunks)\n", s, at, blocks.size(), metric.chunk_count());
}

TEST(SampleBlocks, HoldEverySthSampleOfEachChunkInOrder) {
  merl::Table table;
  for (size_t off = 0; off < merl::kCellCount; ++off)
    table.set_raw(off, 0.1 + 1e-7 * double(off % 977), 0.2, 0.3 + 1e-6 * double(off % 131));
  const MerlBrdf data(std::move(table), "blocks.binary");
  const Metric metric = make_metric("ngan", data, {2});
  for (size_t s : {1, 7, 71}) check_blocks(metric, s);
}

}  // namespace
}  // namespace brdfkit::fit
