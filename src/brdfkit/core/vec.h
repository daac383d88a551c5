#pragma once
// Small vector types and spherical directions in brdfkit's local frame (n = +z, DESIGN.md §2).
// Templated on the scalar so the same code serves doubles and Ceres Jets.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace brdfkit {

template <class T> using Vec3 = Eigen::Matrix<T, 3, 1>;
template <class T> using Vec2 = Eigen::Matrix<T, 2, 1>;
using Vec3d = Vec3<double>;
using Vec2d = Vec2<double>;
using Rgb = Eigen::Array3d;

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kInvPi = std::numbers::inv_pi;

// Wavelengths (µm) of the R, G, B channels where a model needs them (seed 004 §5.5).
inline constexpr double kChannelWavelengthUm[3] = {0.645, 0.526, 0.444};

// Unit direction from polar angle θ (from +z) and azimuth φ.
template <class T> Vec3<T> spherical_direction(const T& theta, const T& phi) {
  using std::cos;
  using std::sin;
  const T s = sin(theta);
  return Vec3<T>(s * cos(phi), s * sin(phi), cos(theta));
}

inline double theta_of(const Vec3d& w) { return std::acos(std::clamp(w.z(), -1.0, 1.0)); }
inline double phi_of(const Vec3d& w) { return std::atan2(w.y(), w.x()); }

// Mirror of w about the unit normal m.
template <class T> Vec3<T> reflect(const Vec3<T>& w, const Vec3<T>& m) { return T(2) * w.dot(m) * m - w; }

}  // namespace brdfkit
