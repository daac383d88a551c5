#include "brdfkit/fit/engine/sample_blocks.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace brdfkit::fit {

namespace {

// At a stride s > 1 a block gathers the every-s-th samples of consecutive chunks until it holds at
// least this many: one chunk's alone would be blocks of 40–400 samples on a MERL table's cells
// (at the start scan's stride and the coarse levels'), whose costs per block (a task, the bases'
// buffers) outweighed their arithmetic.
constexpr size_t kMinGatheredBlock = 2048;

const MetricChunk& cached_chunk(const Metric& metric, size_t i) {
  static thread_local MetricChunk unused;  // fit_model accepts cached metrics only
  return metric.chunk(i, unused);
}

size_t strided_size(const MetricChunk& ch, size_t s) { return (ch.size() + s - 1) / s; }

// The arrays a block reads: the pairs, the measured values, the factor and √w.
constexpr int kArrays = 11;
void arrays_of(const MetricChunk& ch, const double* (&src)[kArrays]) {
  const double* a[kArrays] = {ch.wi_x.data(),        ch.wi_y.data(),        ch.wi_z.data(),
                              ch.wo_x.data(),        ch.wo_y.data(),        ch.wo_z.data(),
                              ch.measured[0].data(), ch.measured[1].data(), ch.measured[2].data(),
                              ch.factor.data(),      ch.sqrt_weight.data()};
  std::copy(a, a + kArrays, src);
}

// b's arrays point at `dst`; its weight (the one the objective reads) from √w.
void finish_block(const double* const (&dst)[kArrays], size_t s, double scale, BlockWeights weights,
                  SampleBlock& b) {
  b.d = {dst[0], dst[1], dst[2], dst[3], dst[4], dst[5]};
  for (int c = 0; c < 3; ++c) b.m[c] = dst[6 + c];
  b.f = dst[9];
  const double* sqrt_weight = dst[10];
  const double root_s = std::sqrt(double(s));
  if (weights == BlockWeights::Residual) {
    b.rw.resize(b.n);
    for (size_t k = 0; k < b.n; ++k) b.rw[k] = scale * sqrt_weight[k] * root_s;
    return;
  }
  b.w2.resize(b.n);
  for (size_t k = 0; k < b.n; ++k) {
    const double w = scale * sqrt_weight[k] * root_s * b.f[k];
    b.w2[k] = w * w;
  }
}

// Stride 1: the chunk's own arrays.
void whole_chunk_block(const MetricChunk& ch, double scale, BlockWeights weights, SampleBlock& b) {
  b.n = ch.size();
  const double* src[kArrays];
  arrays_of(ch, src);
  finish_block(src, 1, scale, weights, b);
}

// Stride s > 1: every s-th sample of chunks [first, last), in chunk order, copied.
void gathered_block(const Metric& metric, size_t first, size_t last, size_t s, BlockWeights weights,
                    SampleBlock& b) {
  b.n = 0;
  for (size_t i = first; i < last; ++i) b.n += strided_size(cached_chunk(metric, i), s);
  b.own.resize(kArrays * b.n);
  const double* dst[kArrays];
  for (int a = 0; a < kArrays; ++a) dst[a] = b.own.data() + size_t(a) * b.n;
  size_t at = 0;
  for (size_t i = first; i < last; ++i) {
    const MetricChunk& ch = cached_chunk(metric, i);
    const size_t m = strided_size(ch, s);
    const double* src[kArrays];
    arrays_of(ch, src);
    for (int a = 0; a < kArrays; ++a) {
      double* out = b.own.data() + size_t(a) * b.n + at;
      for (size_t k = 0; k < m; ++k) out[k] = src[a][k * s];
    }
    at += m;
  }
  finish_block(dst, s, metric.scale(), weights, b);
}

}  // namespace

std::vector<SampleBlock> sample_blocks(const Metric& metric, size_t s, BlockWeights weights) {
  const size_t chunks = metric.chunk_count();
  if (s == 1) {
    std::vector<SampleBlock> blocks(chunks);
    tbb::parallel_for(size_t(0), chunks, [&](size_t i) {
      whole_chunk_block(cached_chunk(metric, i), metric.scale(), weights, blocks[i]);
    });
    return blocks;
  }
  // Block j gathers chunks [ends[j − 1], ends[j]): fixed by the chunks' sizes, whatever the threads.
  std::vector<size_t> ends;
  size_t held = 0;
  for (size_t i = 0; i < chunks; ++i) {
    held += strided_size(cached_chunk(metric, i), s);
    if (held >= kMinGatheredBlock || i + 1 == chunks) {
      ends.push_back(i + 1);
      held = 0;
    }
  }
  std::vector<SampleBlock> blocks(ends.size());
  tbb::parallel_for(size_t(0), blocks.size(), [&](size_t j) {
    gathered_block(metric, j == 0 ? 0 : ends[j - 1], ends[j], s, weights, blocks[j]);
  });
  return blocks;
}

size_t domain_samples(const Metric& metric) {
  size_t n = 0;
  for (size_t i = 0; i < metric.chunk_count(); ++i) n += cached_chunk(metric, i).size();
  return n;
}

}  // namespace brdfkit::fit
