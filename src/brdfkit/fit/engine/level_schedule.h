#pragma once
// The coarse-to-fine levels of a fit: the solver first works on every 67th, 17th and 7th sample of
// the domain, each level starting from the lowest-cost point the previous one evaluated, then on
// the whole domain, which alone decides the result (so it is the full domain's optimum, DESIGN.md
// §7, reached in fewer full-domain iterations, §12). The strides share no factor with the
// domain's rows of 90 or 180 angles (sample_stride.h).
#include <array>
#include <cstddef>
#include <vector>

namespace brdfkit::fit {

inline constexpr std::array<std::size_t, 3> kCoarseStrides = {67, 17, 7};
// A coarse level runs only while it keeps at least this many samples.
inline constexpr std::size_t kMinLevelSamples = 30000;

// The strides of the levels for a domain of `samples` samples, the whole domain (1) last.
inline std::vector<std::size_t> level_strides(std::size_t samples, bool coarse_to_fine) {
  std::vector<std::size_t> out;
  if (coarse_to_fine)
    for (std::size_t s : kCoarseStrides)
      if (samples / s >= kMinLevelSamples) out.push_back(s);
  out.push_back(1);
  return out;
}

}  // namespace brdfkit::fit
