#include <algorithm>

#include "brdfkit/models/model.h"

namespace brdfkit {

Rgb Brdf::eval(const Vec3d& wi, const Vec3d& wo) const {
  Rgb v;
  for (int c = 0; c < 3; ++c) v[c] = model_->eval(values_.channel(c), c, wi, wo);
  return v;
}

std::optional<Vec3d> Brdf::sample(const Vec3d& wo, const Vec2d& u, double u_lobe) const {
  const int c = std::min(2, int(u_lobe * 3.0));
  const double u_rest = u_lobe * 3.0 - c;  // remaining uniform variate for the lobe choice
  return model_->sample(values_.channel(c), c, wo, u, std::min(u_rest, 1.0 - 1e-16));
}

double Brdf::pdf(const Vec3d& wo, const Vec3d& wi) const {
  double sum = 0;
  for (int c = 0; c < 3; ++c) sum += model_->pdf(values_.channel(c), c, wo, wi);
  return sum / 3.0;
}

}  // namespace brdfkit
