#pragma once
// The one residual of every metric (metric.h): r = s·√w·(T(f ρ) − T(f m)), with s·√w the sample's
// residual weight (`rw`), f the cosθi factor or 1, T the metric's transform (identity or ln(1 + ·),
// seed 003 Eq. 31–32). Metric::value and the fitting objectives (fit/engine) compute it here; the
// variable-projection objective uses the identity case written as rw·f·(ρ − m), which it expands
// over the linear bases of ρ.
#include <cmath>

namespace brdfkit::fit {

enum class Transform { Identity, Log1p };

// T(x): identity, or ln(1 + x) guarded for x ≤ −1 (noise below −1 is clamped to −1 + 1e-12 so the
// logarithm stays finite).
inline double apply_transform(Transform t, double x) {
  if (t == Transform::Identity) return x;
  return std::log1p(x > -1.0 + 1e-12 ? x : -1.0 + 1e-12);
}
// T′(x): 1, or 1/(1 + x) — 0 where apply_transform clamps.
inline double transform_slope(Transform t, double x) {
  if (t == Transform::Identity) return 1.0;
  return x > -1.0 + 1e-12 ? 1.0 / (1.0 + x) : 0.0;
}

// T(f m): the measured side, which objectives compute once per domain.
inline double transformed_measured(Transform t, double f, double m) { return apply_transform(t, f * m); }
// rw · (T(f ρ) − tm) with tm = transformed_measured(t, f, m).
inline double metric_residual(Transform t, double rw, double f, double rho, double tm) {
  return rw * (apply_transform(t, f * rho) - tm);
}

}  // namespace brdfkit::fit
