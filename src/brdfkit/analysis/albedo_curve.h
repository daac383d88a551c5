#pragma once
// Directional albedo a(θi) = ∫ ρ cosθo dωo (DESIGN.md §2) of measured data and, optionally, of a
// fitted model, for θi on a degree grid (0°–89° by default), for plotting the two side by side.
#include <optional>
#include <vector>

#include "brdfkit/core/vec.h"
#include "brdfkit/measured/measured_brdf.h"
#include "brdfkit/models/model.h"

namespace brdfkit::analysis {

struct AlbedoCurve {
  std::vector<double> theta_i_deg;
  std::vector<std::optional<Rgb>> data;    // nullopt where the data answer nothing at that θi
  std::vector<double> missing_fraction;    // of ∫ cosθo dωo where the data had no value
  std::vector<std::optional<Rgb>> model;   // nullopt without a model
};

struct AlbedoCurveOptions {
  double from_deg = 0, to_deg = 89, step_deg = 1;
};

// Data: measured/albedo.h's quadrature where eval() answers; the data's own per-θi albedos
// (MeasuredBrdf::albedos_from_samples, e.g. Cornell) otherwise, at the angles they hold.
AlbedoCurve albedo_curve(const MeasuredBrdf& data, const Model* model, const ParamValues* values,
                         const AlbedoCurveOptions& opt = {});

}  // namespace brdfkit::analysis
