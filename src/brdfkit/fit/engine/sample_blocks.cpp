#include "brdfkit/fit/engine/sample_blocks.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace brdfkit::fit {

namespace {

const MetricChunk& cached_chunk(const Metric& metric, size_t i) {
  static thread_local MetricChunk unused;  // fit_model accepts cached metrics only
  return metric.chunk(i, unused);
}

void fill_block(const MetricChunk& ch, size_t s, double scale, SampleBlock& b) {
  b.n = (ch.size() + s - 1) / s;
  constexpr int kArrays = 10;  // the pairs, the measured values and the factor
  const double* src[kArrays] = {ch.wi_x.data(),        ch.wi_y.data(),        ch.wi_z.data(),
                                ch.wo_x.data(),        ch.wo_y.data(),        ch.wo_z.data(),
                                ch.measured[0].data(), ch.measured[1].data(), ch.measured[2].data(),
                                ch.factor.data()};
  const double* dst[kArrays];
  if (s == 1) {
    std::copy(src, src + kArrays, dst);
  } else {
    b.own.resize(kArrays * b.n);
    for (int a = 0; a < kArrays; ++a) {
      double* out = b.own.data() + size_t(a) * b.n;
      for (size_t k = 0; k < b.n; ++k) out[k] = src[a][k * s];
      dst[a] = out;
    }
  }
  b.d = {dst[0], dst[1], dst[2], dst[3], dst[4], dst[5]};
  for (int c = 0; c < 3; ++c) b.m[c] = dst[6 + c];
  b.f = dst[9];
  b.w2.resize(b.n);
  b.rw.resize(b.n);
  for (size_t k = 0; k < b.n; ++k) {
    b.rw[k] = scale * ch.sqrt_weight[k * s] * std::sqrt(double(s));
    const double w = b.rw[k] * b.f[k];
    b.w2[k] = w * w;
  }
}

}  // namespace

std::vector<SampleBlock> sample_blocks(const Metric& metric, size_t s) {
  std::vector<SampleBlock> blocks(metric.chunk_count());
  tbb::parallel_for(size_t(0), blocks.size(),
                    [&](size_t i) { fill_block(cached_chunk(metric, i), s, metric.scale(), blocks[i]); });
  return blocks;
}

size_t domain_samples(const Metric& metric) {
  size_t n = 0;
  for (size_t i = 0; i < metric.chunk_count(); ++i) n += cached_chunk(metric, i).size();
  return n;
}

}  // namespace brdfkit::fit
