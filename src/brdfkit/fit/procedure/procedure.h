#pragma once
// The seeds' fitting procedures (DESIGN.md §8) as presets over fit_model: which metric, which
// steps, which parameters are shared by R, G, B. "Any model can be fitted under any metric with
// shared or per-channel shape parameters; the procedures are presets" (issue #5).
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "brdfkit/fit/engine/variable_projection.h"
#include "brdfkit/measured/measured_brdf.h"
#include "brdfkit/models/model.h"

namespace brdfkit::fit {

struct ProcedureOptions {
  int starts = 1;
  std::uint64_t seed = 1;
  int max_iterations = 100;
  int coarsen = 1;
  std::string metric;              // empty: the procedure's own metric
  bool per_channel_shape = false;  // fit the shape per channel instead of one shape for R, G, B
  std::function<void(std::string_view)> progress;  // optional one-line progress messages
  // hp-2step: a (θh, θd) cell is diffraction-dominated where |det(∇ log ρ, ∇f)| < this (seed 004
  // §4.2's 10⁻²; not scale-free, so an option: DESIGN.md §8).
  double diffraction_threshold = 1e-2;
};

// Known procedure ids, stable order: ngan, bagher, low-e1, low-e2, hp-2step, hp-1step.
std::span<const std::string_view> procedure_ids();

// The metric a procedure optimizes and reports first (ngan → ngan, bagher → bagher, hp-* → hp-rmse …).
std::string_view procedure_metric(std::string_view id);

struct ProcedureResult {
  FitResult fit;
  std::string metric;
  std::vector<std::string> steps;
};

// Throws InputError for an unknown id (listing the known ones) or an incompatible model.
ProcedureResult run_procedure(std::string_view id, const Model& model, const MeasuredBrdf& data,
                              const ProcedureOptions& opt);

}  // namespace brdfkit::fit
