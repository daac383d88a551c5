#pragma once
// Small helpers of the reference transcriptions (tests/models/reference/).
namespace brdfkit::test::ref {

inline double sqr(double x) { return x * x; }
// GLSL's mix / Mitsuba's lerp: a (1 − t) + b t.
inline double mix(double a, double b, double t) { return a * (1 - t) + b * t; }

}  // namespace brdfkit::test::ref
