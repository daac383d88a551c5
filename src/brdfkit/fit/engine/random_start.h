#pragma once
// Starts after the first: each variable uniform in its bounds, log-uniform where the bounds span
// more than two decades (widths and exponents act multiplicatively), from a seeded generator.
#include <cmath>
#include <random>

#include "brdfkit/core/param.h"

namespace brdfkit::fit {

inline double random_start_value(const ParamSpec& s, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double t = u(rng);
  if (!std::isfinite(s.lower) || !std::isfinite(s.upper)) return s.def;
  if (s.lower > 0 && s.upper / s.lower > 100) return s.lower * std::pow(s.upper / s.lower, t);
  return s.lower + t * (s.upper - s.lower);
}

}  // namespace brdfkit::fit
