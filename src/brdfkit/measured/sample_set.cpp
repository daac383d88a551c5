#include "brdfkit/measured/sample_set.h"

namespace brdfkit {

void SampleSet::reserve(size_t n) {
  for (auto* v : {&wi_x, &wi_y, &wi_z, &wo_x, &wo_y, &wo_z, &weight}) v->reserve(n);
  for (auto& c : rgb) c.reserve(n);
  valid.reserve(n);
}

void SampleSet::push_back(const Vec3d& wi, const Vec3d& wo, const Rgb& value, double w, bool is_valid) {
  wi_x.push_back(wi.x());
  wi_y.push_back(wi.y());
  wi_z.push_back(wi.z());
  wo_x.push_back(wo.x());
  wo_y.push_back(wo.y());
  wo_z.push_back(wo.z());
  for (int c = 0; c < 3; ++c) rgb[size_t(c)].push_back(value[c]);
  weight.push_back(w);
  valid.push_back(is_valid ? 1 : 0);
}

}  // namespace brdfkit
