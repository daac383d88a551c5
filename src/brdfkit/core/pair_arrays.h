#pragma once
// Direction pairs in structure-of-arrays form, so loops over pairs vectorize (DESIGN.md §12):
// pair k is wi = (wi_x[k], wi_y[k], wi_z[k]) towards the light, wo = (wo_x[k], …) towards the viewer.
#include <cstddef>
#include <vector>

#include "brdfkit/core/vec.h"

namespace brdfkit {

struct PairArrays {
  std::vector<double> wi_x, wi_y, wi_z, wo_x, wo_y, wo_z;

  void push_pair(const Vec3d& wi, const Vec3d& wo) {
    wi_x.push_back(wi.x());
    wi_y.push_back(wi.y());
    wi_z.push_back(wi.z());
    wo_x.push_back(wo.x());
    wo_y.push_back(wo.y());
    wo_z.push_back(wo.z());
  }
  void reserve_pairs(std::size_t n) {
    for (auto* v : {&wi_x, &wi_y, &wi_z, &wo_x, &wo_y, &wo_z}) v->reserve(n);
  }
  Vec3d wi(std::size_t k) const { return {wi_x[k], wi_y[k], wi_z[k]}; }
  Vec3d wo(std::size_t k) const { return {wo_x[k], wo_y[k], wo_z[k]}; }
};

}  // namespace brdfkit
