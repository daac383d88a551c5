#pragma once
// What the renderer shades with: ρ(wi, wo) in RGB in the local frame (n = +z, wi towards the
// light, DESIGN.md §2) with a sampler of wi given wo and its density. An analytic model samples
// itself (its own importance sampling); measured data are sampled through a proxy.
#include <memory>
#include <optional>
#include <string>

#include "brdfkit/core/vec.h"
#include "brdfkit/measured/measured_brdf.h"
#include "brdfkit/models/model.h"

namespace brdfkit::render {

class Reflector {
 public:
  virtual ~Reflector() = default;
  virtual Rgb eval(const Vec3d& wi, const Vec3d& wo) const = 0;
  // wi drawn with density pdf(wo, wi) over the upper hemisphere (nullopt: the draw was lost,
  // which pdf's missing mass accounts for).
  virtual std::optional<Vec3d> sample(const Vec3d& wo, const Vec2d& u, double u_lobe) const = 0;
  virtual double pdf(const Vec3d& wo, const Vec3d& wi) const = 0;
};

// A model with its values, sampled by Brdf::sample (the model's own sampler).
std::unique_ptr<Reflector> model_reflector(const Brdf& brdf);

// Measured data: ρ(wi, wo) = max(0, data.eval(wo, wi)) (negative entries are noise and are clamped
// for rendering, DESIGN.md §2; directions the data do not answer give 0). The data are asked with
// the view direction first, i.e. an RGL table is conditioned on the view direction, as Mitsuba 3's
// `measured` plugin renders these files (its si.wi points to the camera): a pixel then integrates
// the very slice whose integral `brdfkit info` reports as the albedo at that angle, so a white
// furnace shows the data's albedo. RGL data are not reciprocal (DESIGN.md §2), so conditioning
// on the light instead changes a render (up to 20 % for vch_golden_yellow); MERL tables are
// reciprocal by construction. Sampled by a defensive mixture
// (Hesterberg 1995): with probability 3/4 the proxy model (a fit of these data), otherwise the
// cosine-weighted hemisphere; without a proxy, cosine sampling alone. `data` must outlive it.
std::unique_ptr<Reflector> measured_reflector(const MeasuredBrdf& data, const std::optional<Brdf>& proxy);

}  // namespace brdfkit::render
