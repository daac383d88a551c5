#pragma once
// A metric = a sample domain (metric_grid.h) + a residual (DESIGN.md §7). The same object gives
// the solver its residual vector and reports give one number:
//   r(k, c) = s · √w_k · (T(f_k ρ_c) − T(f_k m_c)),   value = post(Σ_k,c r²)
// with w the quadrature weight, f the cosθi factor or 1, T the identity or ln(1 + ·) (seed 003
// Eq. 31–32), s a global scale (normalizations) and post = √ or the identity (seed 003 Eq. 33
// is a sum of squares).
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "brdfkit/core/error.h"
#include "brdfkit/core/registry.h"
#include "brdfkit/fit/metric/metric_cells.h"
#include "brdfkit/fit/metric/metric_grid.h"
#include "brdfkit/fit/metric/residual.h"
#include "brdfkit/measured/measured_brdf.h"
#include "brdfkit/models/model.h"

namespace brdfkit::fit {

// The data answer nothing in a metric's domain (scattered samples, empty tables) or have no
// albedo to normalize by: a property of the data, so reports show "n/a" for that metric.
class MetricUndefined : public InputError {
 public:
  using InputError::InputError;
};

// Where a metric samples a MERL table: its own cells (metric_cells.h: values exact at the cell
// centres, the metric's weights carried over), or the paper's (θi, θo, Δφ) grid looked up in the
// nearest cell. Scattered data (metric_samples.h) always use their own samples, other data the grid.
enum class MetricDomain { Auto, Grid };

struct MetricOptions {
  // Widens every grid step by this integer factor (1 = the paper's grid; on MERL cells: one cell
  // per k × k × k block of indices). Only for tests and quick looks where the paper's grid is
  // not the point (DESIGN.md §7 warns against fitting on coarser grids).
  int coarsen = 1;
  MetricDomain domain = MetricDomain::Auto;  // Auto: a MERL table's cells where the metric has them
  // Keep a grid's or a MERL table's cells' samples (a fit evaluates them hundreds of times), or
  // build them again at every value(): a metric only reported, once per fit, where keeping the
  // grid of each material in flight would cost 25–130 MB per metric (bench/main_job.sh's RSS),
  // a MERL table's cells 80–160 MB.
  bool keep = true;
};

class Metric {
 public:
  std::string_view id() const { return id_; }
  Transform transform() const { return transform_; }
  bool takes_sqrt() const { return sqrt_; }
  double scale() const { return scale_; }
  // The normalizing albedo (max measured albedo over θi ≤ 80°) or 1 where the metric has none.
  double albedo_norm() const { return albedo_norm_; }
  size_t chunk_count() const;
  // Chunk i: the cached one, or built into `scratch` for a domain not kept (hp-rmse's grid,
  // MetricOptions::keep = false).
  const MetricChunk& chunk(size_t i, MetricChunk& scratch) const;
  bool cached() const { return !chunks_.empty(); }
  // Valid samples over all chunks (cached metrics only; 0 otherwise).
  size_t sample_count() const;
  // Whether the domain is a MERL table's cells ("cells") or the paper's grid ("grid").
  bool on_cells() const { return on_cells_; }
  // Whether the domain is scattered data's own samples (metric_samples.h).
  bool on_samples() const { return on_samples_; }
  // The cells domain folds both orientations of a cell into one sample (metric_cells.h), which
  // is exact only for reciprocal models: value() and fit_model() refuse the others (InputError).
  bool needs_reciprocal_model() const { return folded_; }
  void check_model(const Model& model) const;

  // The metric's value for a model with parameter values (parallel, deterministic order).
  double value(const Model& model, const ParamValues& values) const;

  // Post-processing of a pooled sum of squared residuals into the reported number.
  double finish(double sum_sq) const;

 private:
  friend Metric build_metric(std::string_view id, const MeasuredBrdf& data, const MetricOptions& opt,
                             const std::function<double(int)>& max_albedo);
  std::string id_;
  GridSpec grid_;
  Transform transform_ = Transform::Identity;
  bool sqrt_ = true;
  double scale_ = 1.0;
  double albedo_norm_ = 1.0;
  std::vector<MetricChunk> chunks_;
  bool on_cells_ = false;
  bool on_samples_ = false;
  bool folded_ = false;
  CellWeighting cell_weighting_;  // a cells domain built on demand
  int coarsen_ = 1;
  const MeasuredBrdf* data_ = nullptr;  // for chunks built on demand; must outlive the metric
};

struct MetricDefinition;
// A metric's definition at a grid coarsening (metric_definition.h: one file per paper's metric).
using MetricDefinitionAt = MetricDefinition (*)(int coarsen);
// The metrics of DESIGN.md §7 in a stable order: ngan, bagher, low-e1, low-e2, hp-rmse.
const Registry<MetricDefinitionAt>& metric_registry();
std::vector<std::string> metric_ids();

// Builds a metric over `data` (which must outlive it); throws InputError for unknown ids or data
// without the reflectance the metric needs. The normalizing albedo is integrated here; a
// MetricStore (metric_store.h) builds each metric once and integrates the albedo once per data.
Metric make_metric(std::string_view id, const MeasuredBrdf& data, const MetricOptions& opt = {});
// make_metric with the maximum measured albedo at a coarsening taken from `max_albedo`.
Metric build_metric(std::string_view id, const MeasuredBrdf& data, const MetricOptions& opt,
                    const std::function<double(int)>& max_albedo);

}  // namespace brdfkit::fit
