#pragma once
// A deterministic parallel reduction: `chunks` pieces of work each fill `width` partial sums,
// computed in parallel (TBB), then added up in chunk order. The result does not depend on the
// thread count or on scheduling, so a fit or a metric gives the same bits on every run
// ("same inputs, same outputs").
#include <tbb/parallel_for.h>

#include <cstddef>
#include <vector>

namespace brdfkit {

// fill(i, acc): adds chunk i's contributions into acc[0 .. width), which starts at zero.
// Returns the chunk-ordered sums.
template <class Fill> std::vector<double> ordered_reduce(std::size_t chunks, std::size_t width, Fill&& fill) {
  std::vector<double> partial(chunks * width, 0.0);
  tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t i) { fill(i, partial.data() + i * width); });
  std::vector<double> total(width, 0.0);
  for (std::size_t i = 0; i < chunks; ++i)
    for (std::size_t k = 0; k < width; ++k) total[k] += partial[i * width + k];
  return total;
}

}  // namespace brdfkit
