#pragma once
// The bound readers put on measured values (MERL, Cornell).

namespace brdfkit {

// The largest value, in sr⁻¹, that readers accept as a measurement. No measurement comes near it
// (a perfect mirror seen through a 1e-9 sr aperture reads ~1e9), and below it a sum of squares
// over every value of a file (means, albedos, metrics: ~1e7 terms of at most 1e200) stays far
// from overflow, so an accepted file never makes a statistic infinite or NaN.
inline constexpr double kMaxMeasuredValue = 1e100;

}  // namespace brdfkit
