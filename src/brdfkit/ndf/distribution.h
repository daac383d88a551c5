#pragma once
// What a microfacet distribution of ndf/ is (the shape of pbrt-v4's TrowbridgeReitzDistribution in
// spirit): a value type templated on the scalar (double or ceres::Jet), built from the model's
// parameter values, with
//   static constexpr std::string_view kName, kTitle;   "ggx", "GGX": the catalogue's names
//   static ParamTable params();                         names, bounds, defaults (all Scope::Shared)
//   explicit X(const T* p);                             from parameter values in params() order
//   T D(const T& cos_theta) const;                      normalized: ∫ D(ωm) cosθm dωm = 1, 0 for cosθ ≤ 0
//   T P22(const T& x) const;                            slope-space form, x = tan²θ (seed 000 Eq. 2–3)
//   T unit(const T& cos_theta) const;                   D/D(0), the peak-normalized shape (seed 001)
//   Vec3d sample(const Vec2d& u) const;                 microfacet normal m with density D(m) cosθm
//   double pdf(const Vec3d& m) const;                   = D(m) cosθm
// and its Smith shape, which shadowing/smith.h reads (one of):
//   T Lambda(const T& tan_theta) const;                 a closed form;
//   a specialization SmithShape<X> (below)              the numeric Λ tabulated on its axes;
//   neither                                             the direct integral of P22.
// One-parameter distributions that seed 001's conversions compare also declare
//   static constexpr UnitFormRange kUnitForm;           symbol and range of the unit-form comparison
// (analysis/ndf_conversion.h). ndf/distributions.h lists every distribution once: the Cook-Torrance
// models, the back-scatter families, `convert-ndf` and the typed tests are generated from it.
#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <string_view>
#include <vector>

#include "brdfkit/core/param.h"
#include "brdfkit/core/vec.h"

namespace brdfkit {

// One coordinate axis of a tabulated Smith Λ (shadowing/smith_table.h).
struct SmithAxis {
  double lo;
  double hi;
  int n;           // nodes, ≥ 4
  bool log_scale;  // interpolate in log(value)
};

// The table of a distribution family's numeric Smith Λ (shadowing/smith_table.h). A
// specialization SmithShape<Ndf> provides
//   static constexpr int kDims;                                 1 to 3 table coordinates
//   static std::vector<SmithAxis> axes();                       box and grid of the coordinates
//   template <class T> static std::array<T, kDims> values(const Ndf<T>&);   the coordinates
// and optionally
//   static Ndf<double> make(const double* coords);              the distribution at coordinates;
//                                                               default Ndf<double>(coords), i.e.
//                                                               coordinates = params() values
//   template <class T> static T tan_edge(const T* coords);      support edge t_e (Λ = 0 for
//                                                               tanθ ≤ t_e), for compact supports
// The primary template has no table (kDims = 0).
template <template <class> class Ndf> struct SmithShape {
  static constexpr int kDims = 0;
};

// The parameter range in which D(0) is the maximum of D and the unit form D/D(0) a single
// decreasing lobe (seed 001's D/max D), with seed 001's symbol for the parameter.
struct UnitFormRange {
  std::string_view symbol;
  double lower, upper;
  std::string_view formula;  // the unit form with its source, for listings
};

// The unit vector at polar cosine cos_theta and azimuth 2π u_phi: the last step of every isotropic
// sampler, whose inverted CDF gives cos θm and whose azimuth is uniform.
inline Vec3d isotropic_normal(double cos_theta, double u_phi) {
  const double s = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  const double phi = 2 * kPi * u_phi;
  return Vec3d(s * std::cos(phi), s * std::sin(phi), cos_theta);
}

template <template <class> class Ndf>
concept Distribution = requires(const Ndf<double>& d, const double* p, double c, const Vec2d& u, const Vec3d& m) {
  { Ndf<double>::kName } -> std::convertible_to<std::string_view>;
  { Ndf<double>::kTitle } -> std::convertible_to<std::string_view>;
  { Ndf<double>::params() } -> std::same_as<ParamTable>;
  Ndf<double>(p);
  { d.D(c) } -> std::same_as<double>;
  { d.P22(c) } -> std::same_as<double>;
  { d.unit(c) } -> std::same_as<double>;
  { d.sample(u) } -> std::same_as<Vec3d>;
  { d.pdf(m) } -> std::same_as<double>;
};

}  // namespace brdfkit
