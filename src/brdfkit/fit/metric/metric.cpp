#include "brdfkit/fit/metric/metric.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <array>
#include <cmath>

#include "brdfkit/core/error.h"
#include "brdfkit/core/ordered_reduce.h"
#include "brdfkit/core/thread_scratch.h"
#include "brdfkit/fit/metric/metric_definition.h"

namespace brdfkit::fit {

const Registry<MetricDefinitionAt>& metric_registry() {
  static const Registry<MetricDefinitionAt> registry = [] {
    Registry<MetricDefinitionAt> r("metric");
    r.add("ngan", &ngan_metric)
        .add("bagher", &bagher_metric)
        .add("low-e1", [](int coarsen) { return low_metric(1, coarsen); })
        .add("low-e2", [](int coarsen) { return low_metric(2, coarsen); })
        .add("hp-rmse", &hp_rmse_metric);
    return r;
  }();
  return registry;
}

std::vector<std::string> metric_ids() { return metric_registry().names(); }

namespace {

struct DomainTotals {
  double weight_sum = 0;  // Σ w over the domain, in chunk order
  size_t samples = 0;
};

size_t sample_total(const std::vector<MetricChunk>& chunks) {
  size_t n = 0;
  for (const MetricChunk& ch : chunks) n += ch.size();
  return n;
}

// The paper's grid with the measured value looked up, node by node: kept in `chunks`, or (not
// `keep`) looked up only for the totals here and again by each value().
DomainTotals grid_domain(const GridSpec& grid, const MeasuredBrdf& data, bool keep, std::vector<MetricChunk>& chunks) {
  const size_t n = grid.theta_i.size();
  std::vector<double> weight(n, 0.0);
  std::vector<size_t> samples(n, 0);
  if (keep) chunks.resize(n);
  tbb::parallel_for(size_t(0), n, [&](size_t i) {
    ScratchLease<MetricChunk> scratch;
    MetricChunk& ch = keep ? chunks[i] : *scratch;
    build_chunk(grid, i, data, ch);
    for (double s : ch.sqrt_weight) weight[i] += s * s;
    samples[i] = ch.size();
  });
  DomainTotals t;
  for (size_t i = 0; i < n; ++i) {
    t.weight_sum += weight[i];
    t.samples += samples[i];
  }
  return t;
}

// A MERL table's cells chunk by chunk, for the totals only (a domain not kept).
DomainTotals cell_totals(const merl::Table& table, const CellWeighting& weighting, int coarsen) {
  const size_t n = cell_chunk_count(coarsen);
  std::vector<double> measure(n, 0.0);
  std::vector<size_t> samples(n, 0);
  tbb::parallel_for(size_t(0), n, [&](size_t i) {
    ScratchLease<MetricChunk> scratch;
    measure[i] = build_cell_chunk(table, weighting, coarsen, i, *scratch);
    samples[i] = scratch->size();
  });
  DomainTotals t;
  for (size_t i = 0; i < n; ++i) {  // chunk order: deterministic
    t.weight_sum += measure[i];
    t.samples += samples[i];
  }
  return t;
}

// The domain a definition gives on these data: the data's own samples (scattered formats, and
// anisotropic tables, which a grid with wi at φ = 0 would see in one azimuth only), a MERL
// table's cells, or the paper's grid (kept where the definition and the options allow; built on
// demand otherwise).
DomainTotals build_domain(const MetricDefinition& def, const MeasuredBrdf& data, const MetricOptions& opt,
                          std::vector<MetricChunk>& chunks, bool& on_samples, bool& on_cells) {
  const merl::Table* cells = data.merl_cells();
  if (!cells && def.cells.density && (!data.isotropic() || is_scattered(data))) {
    SampleDomain samples = build_sample_domain(data.samples(), def.cells.density, def.grid.cos_i_factor);
    chunks = std::move(samples.chunks);
    on_samples = true;
    return {samples.measure_sum, sample_total(chunks)};
  }
  if (cells && def.cells.density && opt.domain == MetricDomain::Auto) {
    on_cells = true;
    if (!opt.keep) return cell_totals(*cells, def.cells, opt.coarsen);
    CellDomain domain = build_cell_domain(*cells, def.cells, opt.coarsen);
    chunks = std::move(domain.chunks);
    return {domain.measure_sum, sample_total(chunks)};
  }
  if (!def.cache) return {};
  return grid_domain(def.grid, data, opt.keep, chunks);
}

}  // namespace

Metric build_metric(std::string_view id, const MeasuredBrdf& data, const MetricOptions& opt,
                    const std::function<double(int)>& max_albedo) {
  if (opt.coarsen < 1) throw InputError("metric '" + std::string(id) + "'", "coarsening factor must be >= 1");
  const MetricDefinition def = metric_registry().get(id)(opt.coarsen);
  Metric m;
  m.id_ = std::string(id);
  m.grid_ = def.grid;
  m.transform_ = def.transform;
  m.sqrt_ = def.sqrt;
  m.data_ = &data;
  // The domain and the albedo norm read the data only: built side by side, the albedo's trigonometry
  // fills the cores while the domain's passes wait on memory.
  DomainTotals totals;
  tbb::parallel_invoke(
      [&] { totals = build_domain(def, data, opt, m.chunks_, m.on_samples_, m.on_cells_); },
      [&] {
        if (def.divide_by_max_albedo) m.albedo_norm_ = max_albedo(opt.coarsen);
      });
  m.folded_ = m.on_cells_ && def.cells.fold;
  m.cell_weighting_ = def.cells;
  m.coarsen_ = opt.coarsen;
  if ((def.cache || m.on_samples_ || m.on_cells_) && totals.samples == 0)
    throw MetricUndefined(data.path(), "no measured value in the domain of metric '" + m.id_ + "'");
  double scale2 = def.channel_pool;
  if (def.divide_by_weight_sum) scale2 /= totals.weight_sum;
  if (def.divide_by_max_albedo) {
    if (!(m.albedo_norm_ > 0) || !std::isfinite(m.albedo_norm_))
      throw MetricUndefined(data.path(), "maximum measured albedo is not positive; metric '" + m.id_ +
                                             "' is normalized by it and undefined");
  }
  m.scale_ = std::sqrt(scale2) / (def.sqrt ? m.albedo_norm_ : 1.0);
  return m;
}

Metric make_metric(std::string_view id, const MeasuredBrdf& data, const MetricOptions& opt) {
  return build_metric(id, data, opt, [&](int coarsen) { return max_measured_albedo(data, coarsen); });
}

size_t Metric::chunk_count() const {
  if (cached()) return chunks_.size();
  return on_cells_ ? cell_chunk_count(coarsen_) : grid_.theta_i.size();
}

const MetricChunk& Metric::chunk(size_t i, MetricChunk& scratch) const {
  if (cached()) return chunks_[i];
  if (on_cells_)
    build_cell_chunk(*data_->merl_cells(), cell_weighting_, coarsen_, i, scratch);
  else
    build_chunk(grid_, i, *data_, scratch);
  return scratch;
}

void Metric::check_model(const Model& model) const {
  if (folded_ && !model.reciprocal())
    throw InputError("model '" + std::string(model.name()) + "'",
                     "is not reciprocal; metric '" + id_ +
                         "' on a MERL table's cells assumes reciprocity (use the grid domain)");
}

size_t Metric::sample_count() const { return sample_total(chunks_); }

double Metric::finish(double sum_sq) const { return sqrt_ ? std::sqrt(sum_sq) : sum_sq; }

double Metric::value(const Model& model, const ParamValues& values) const {
  check_model(model);
  // Per chunk: Σ r² (the residual of residual.h, scale applied at the end), its sample count, and
  // whether the sum is finite.
  struct Buffers {
    MetricChunk chunk;         // an on-demand grid's chunk
    std::array<std::vector<double>, 3> rho;
  };
  const std::vector<double> total = ordered_reduce(chunk_count(), 3, [&](size_t i, double* acc) {
    ScratchLease<Buffers> buffers;
    const MetricChunk& ch = chunk(i, buffers->chunk);
    double sum = 0;
    auto& rho = buffers->rho;
    for (auto& r : rho) r.resize(ch.size());
    const SoaPairs d{ch.wi_x.data(), ch.wi_y.data(), ch.wi_z.data(), ch.wo_x.data(), ch.wo_y.data(), ch.wo_z.data()};
    const double* const p[3] = {values.channel(0), values.channel(1), values.channel(2)};
    double* const out[3] = {rho[0].data(), rho[1].data(), rho[2].data()};
    model.eval_batch_rgb(p, ch.size(), d, out);
    for (int c = 0; c < 3; ++c) {
      const auto& meas = ch.measured[size_t(c)];
      const auto& rho_c = rho[size_t(c)];
      for (size_t k = 0; k < ch.size(); ++k) {
        const double f = ch.factor[k];
        const double r =
            metric_residual(transform_, ch.sqrt_weight[k], f, rho_c[k], transformed_measured(transform_, f, meas[k]));
        sum += r * r;
      }
    }
    acc[0] = sum;
    acc[1] = double(ch.size());
    acc[2] = std::isfinite(sum) ? 0.0 : 1.0;
  });
  if (total[2] > 0)
    throw InputError("parameters of model '" + std::string(model.name()) + "'",
                     "the model evaluates to a non-finite value in the domain of metric '" + id_ + "'");
  if (total[1] == 0) throw MetricUndefined(data_->path(), "no measured value in the domain of metric '" + id_ + "'");
  return finish(scale_ * scale_ * total[0]);
}

double max_measured_albedo(const MeasuredBrdf& data, int coarsen) {
  const double deg = kPi / 180.0;
  const auto given = data.albedos_from_samples();
  if (!given.empty()) {
    double best = 0;
    for (const auto& [theta, a] : given)
      if (theta <= 80 * deg + 1e-9) best = std::max(best, a.maxCoeff());
    return best;
  }
  const int n_i = 80 / coarsen;
  const auto ti = cell_centres(0.0, n_i * coarsen * deg, n_i);
  const auto to = cell_centres(0.0, kPi / 2, 90 / coarsen);
  const auto ph = cell_centres(0.0, kPi, 180 / coarsen, 2.0);  // Δφ ∈ [π, 2π) mirrors [0, π)
  // The outgoing directions and their weights cosθo dωo are the same for every θi.
  std::vector<Vec3d> wo;
  std::vector<double> w;
  for (const AxisNode& o : to) {
    const double st = std::sin(o.angle), ct = std::cos(o.angle);
    for (const AxisNode& p : ph) {
      wo.emplace_back(st * std::cos(p.angle), st * std::sin(p.angle), ct);
      w.push_back(ct * st * o.weight * p.weight);
    }
  }
  std::vector<double> best(ti.size(), 0.0);
  tbb::parallel_for(size_t(0), ti.size(), [&](size_t i) {
    const Vec3d wi(std::sin(ti[i].angle), 0.0, std::cos(ti[i].angle));
    std::vector<std::optional<Rgb>> m;
    data.eval_row(wi, wo, m);
    Rgb a = Rgb::Zero();
    for (size_t k = 0; k < wo.size(); ++k)
      if (m[k] && m[k]->allFinite()) a += *m[k] * w[k];  // ρ cosθo dωo
    best[i] = a.maxCoeff();
  });
  double out = 0;
  for (double b : best) out = std::max(out, b);
  return out;
}

}  // namespace brdfkit::fit
