#include "brdfkit/measured/sample_set.h"

namespace brdfkit {

void SampleSet::reserve(size_t n) {
  reserve_pairs(n);
  weight.reserve(n);
  for (auto& c : rgb) c.reserve(n);
  valid.reserve(n);
}

void SampleSet::push_back(const Vec3d& wi, const Vec3d& wo, const Rgb& value, double w, bool is_valid) {
  push_pair(wi, wo);
  for (int c = 0; c < 3; ++c) rgb[size_t(c)].push_back(value[c]);
  weight.push_back(w);
  valid.push_back(is_valid ? 1 : 0);
}

}  // namespace brdfkit
