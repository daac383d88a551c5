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
  std::vector<double> w2;      // (scale · √w · f)² · stride: the identity residual's weight
  std::vector<double> rw;      // scale · √w · √stride: residual.h's rw
  std::vector<double> own;     // gathered arrays (stride > 1)
};

// One block per chunk of the metric's (cached) domain at stride s.
std::vector<SampleBlock> sample_blocks(const Metric& metric, std::size_t s);

// Samples in the metric's cached domain.
std::size_t domain_samples(const Metric& metric);

}  // namespace brdfkit::fit
