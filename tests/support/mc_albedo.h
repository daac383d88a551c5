#pragma once
// Directional albedo by importance sampling with a model's own sampler (stratified, seeded):
// a(θ) = E[ρ(wi, wo) cosθi / pdf(wi)], wo at polar angle θ (= ∫ ρ cosθ dω by reciprocity).
// Sharp lobes (N ~ 10⁶, B ~ 10⁶) defeat fixed quadrature; the sampler follows them.
#include <cstdint>
#include <random>

#include "brdfkit/models/model.h"

namespace brdfkit::test {

inline double mc_albedo(const Model& m, const double* p, int c, double theta, int n_sqrt = 64,
                        std::uint64_t seed = 42) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const Vec3d wo = spherical_direction(theta, 0.0);
  double sum = 0;
  for (int i = 0; i < n_sqrt; ++i)
    for (int j = 0; j < n_sqrt; ++j) {
      const Vec2d u((i + u01(rng)) / n_sqrt, (j + u01(rng)) / n_sqrt);
      const auto wi = m.sample(p, c, wo, u, u01(rng));
      if (!wi) continue;
      const double pdf = m.pdf(p, c, wo, *wi);
      if (pdf > 0) sum += m.eval(p, c, *wi, wo) * wi->z() / pdf;
    }
  return sum / (double(n_sqrt) * n_sqrt);
}

// Linear sRGB luminance Y (the weights DESIGN.md §2 gives for RGL files).
inline double luminance(double r, double g, double b) { return 0.212671 * r + 0.715160 * g + 0.072169 * b; }

}  // namespace brdfkit::test
