#pragma once
// A metric's cached domain as the solver sees it at one sample stride: every s-th sample of each
// chunk, weighted s times (s = 1: the whole domain), with the parts of the residual that do not
// depend on the model gathered once per stride.
#include <cstddef>
#include <vector>

#include "brdfkit/fit/metric/metric.h"
#include "brdfkit/models/model.h"

namespace brdfkit::fit {

struct SampleBlock {
  std::size_t n = 0;
  SoaPairs d{};
  const double* m[3] = {};     // measured ρ per channel
  const double* f = nullptr;   // the factor of ρ: residual.h's f
  // The objective's weight (BlockWeights): one of w2 and rw is filled, the other left empty.
  std::vector<double> w2;      // (scale · √w · f)² · stride: the identity residual's weight
  std::vector<double> rw;      // scale · √w · √stride: residual.h's rw
  std::vector<double> own;     // gathered arrays (stride > 1)
};

// The weight an objective reads: variable projection's inner products take w², a residual
// objective (plain, log) takes rw. Only that one is filled: on a MERL table's 1.4 M cells each
// is 11 MB of fresh pages per level.
enum class BlockWeights { Squared, Residual };

// The metric's (cached) domain at stride s in blocks: one per chunk at s = 1, consecutive chunks
// gathered into blocks of at least 2048 samples at s > 1.
std::vector<SampleBlock> sample_blocks(const Metric& metric, std::size_t s, BlockWeights weights);

// Samples in the metric's cached domain.
std::size_t domain_samples(const Metric& metric);

}  // namespace brdfkit::fit
