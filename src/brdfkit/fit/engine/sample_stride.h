#pragma once
// Strides for subsampling a metric domain (the start scan and the coarse-to-fine levels of the
// solver take every s-th sample of each chunk).
#include <cstddef>
#include <numeric>

namespace brdfkit::fit {

// The smallest stride ≥ s that shares no factor with 30. Domains are laid out in rows of 90 or 180
// angles (2²·3²·5): a stride sharing a factor with them takes the same few Δφ columns in every row.
// Stride 4 saw a quarter of them and none at the mirror plane, so a He fit on an RGL material
// left its stride-4 level at 1.7e-2 and then moved by |step| ≈ 3 on the whole domain.
inline std::size_t coprime_stride(std::size_t s) {
  if (s < 1) s = 1;
  while (std::gcd(s, std::size_t(30)) != 1) ++s;
  return s;
}

}  // namespace brdfkit::fit
