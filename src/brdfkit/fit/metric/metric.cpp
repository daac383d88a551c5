#include "brdfkit/fit/metric/metric.h"

#include <tbb/parallel_for.h>

#include <array>
#include <cmath>

#include "brdfkit/core/error.h"
#include "brdfkit/fit/metric/metric_cache.h"
#include "brdfkit/fit/metric/metric_definition.h"
#include "brdfkit/measured/merl_brdf.h"

namespace brdfkit::fit {

namespace {

constexpr std::string_view kIds[] = {"ngan", "bagher", "low-e1", "low-e2", "hp-rmse"};

MetricDefinition definition(std::string_view id, int coarsen) {
  if (id == "ngan") return ngan_metric(coarsen);
  if (id == "bagher") return bagher_metric(coarsen);
  if (id == "low-e1") return low_metric(1, coarsen);
  if (id == "low-e2") return low_metric(2, coarsen);
  if (id == "hp-rmse") return hp_rmse_metric(coarsen);
  std::string known;
  for (auto k : kIds) known += (known.empty() ? "" : ", ") + std::string(k);
  throw InputError("metric '" + std::string(id) + "'", "unknown; known metrics: " + known);
}

}  // namespace

std::span<const std::string_view> metric_ids() { return kIds; }

Metric make_metric(std::string_view id, const MeasuredBrdf& data, const MetricOptions& opt) {
  if (opt.coarsen < 1) throw InputError("metric '" + std::string(id) + "'", "coarsening factor must be >= 1");
  if (auto kept = detail::find_cached_metric(data, id, opt)) return *kept;
  const MetricDefinition def = definition(id, opt.coarsen);
  Metric m;
  m.id_ = std::string(id);
  m.grid_ = def.grid;
  m.transform_ = def.transform;
  m.sqrt_ = def.sqrt;
  m.data_ = &data;
  double scale2 = def.channel_pool;
  double wsum = 0;  // Σ w over the domain, in chunk order: deterministic
  const auto* merl = dynamic_cast<const MerlBrdf*>(&data);
  const auto sample_density = def.sample_density ? def.sample_density : def.cells.density;
  if (!merl && sample_density && is_scattered(data)) {
    SampleDomain samples = build_sample_domain(data.samples(), sample_density, def.grid.cos_i_factor);
    m.chunks_ = std::move(samples.chunks);
    m.on_samples_ = true;
    wsum = samples.measure_sum;
  } else if (merl && def.cells.density && opt.domain == MetricDomain::Auto) {
    CellDomain cells = build_cell_domain(merl->table(), def.cells, opt.coarsen);
    m.chunks_ = std::move(cells.chunks);
    m.on_cells_ = true;
    m.folded_ = def.cells.fold;
    wsum = cells.measure_sum;
  } else if (def.cache) {
    m.chunks_.resize(m.grid_.theta_i.size());
    tbb::parallel_for(size_t(0), m.chunks_.size(), [&](size_t i) { m.chunks_[i] = build_chunk(m.grid_, i, data); });
    for (const MetricChunk& ch : m.chunks_)
      for (double s : ch.sqrt_weight) wsum += s * s;
  }
  if ((def.cache || m.on_samples_) && m.sample_count() == 0)
    throw MetricUndefined(data.path(), "no measured value in the domain of metric '" + m.id_ + "'");
  if (def.divide_by_weight_sum) scale2 /= wsum;
  if (def.divide_by_max_albedo) {
    m.albedo_norm_ = max_measured_albedo(data, opt.coarsen);
    if (!(m.albedo_norm_ > 0) || !std::isfinite(m.albedo_norm_))
      throw MetricUndefined(data.path(), "maximum measured albedo is not positive; metric '" + m.id_ +
                                        "' is normalized by it and undefined");
  }
  m.scale_ = std::sqrt(scale2) / (def.sqrt ? m.albedo_norm_ : 1.0);
  detail::keep_metric(data, id, opt, m);
  return m;
}

std::shared_ptr<const Metric> shared_metric(std::string_view id, const MeasuredBrdf& data, const MetricOptions& opt) {
  if (auto kept = detail::find_cached_metric(data, id, opt)) return kept;
  Metric m = make_metric(id, data, opt);
  if (auto kept = detail::find_cached_metric(data, id, opt)) return kept;  // kept by make_metric
  return std::make_shared<const Metric>(std::move(m));
}

const MetricChunk& Metric::chunk(size_t i, MetricChunk& scratch) const {
  if (!chunks_.empty()) return chunks_[i];
  scratch = build_chunk(grid_, i, *data_);
  return scratch;
}

void Metric::check_model(const Model& model) const {
  if (folded_ && !model.reciprocal())
    throw InputError("model '" + std::string(model.name()) + "'",
                     "is not reciprocal; metric '" + id_ +
                         "' on a MERL table's cells assumes reciprocity (use the grid domain)");
}

size_t Metric::sample_count() const {
  size_t n = 0;
  for (const MetricChunk& ch : chunks_) n += ch.size();
  return n;
}

double Metric::finish(double sum_sq) const { return sqrt_ ? std::sqrt(sum_sq) : sum_sq; }

double Metric::value(const Model& model, const ParamValues& values) const {
  check_model(model);
  std::vector<double> partial(chunk_count(), 0.0);
  std::vector<unsigned char> bad(chunk_count(), 0);
  std::vector<size_t> count(chunk_count(), 0);
  tbb::parallel_for(size_t(0), chunk_count(), [&](size_t i) {
    MetricChunk scratch;
    const MetricChunk& ch = chunk(i, scratch);
    count[i] = ch.size();
    double sum = 0;
    std::vector<double> rho(ch.size());
    const SoaPairs d{ch.wi_x.data(), ch.wi_y.data(), ch.wi_z.data(), ch.wo_x.data(), ch.wo_y.data(), ch.wo_z.data()};
    for (int c = 0; c < 3; ++c) {
      model.eval_batch(values.channel(c), c, ch.size(), d, rho.data());
      const auto& meas = ch.measured[size_t(c)];
      for (size_t k = 0; k < ch.size(); ++k) {
        const double f = ch.factor[k];
        const double r =
            ch.sqrt_weight[k] * (apply_transform(transform_, f * rho[k]) - apply_transform(transform_, f * meas[k]));
        sum += r * r;
      }
    }
    partial[i] = sum;
    bad[i] = !std::isfinite(sum);
  });
  double total = 0;
  for (size_t i = 0; i < partial.size(); ++i) {
    if (bad[i])
      throw InputError("parameters of model '" + std::string(model.name()) + "'",
                       "the model evaluates to a non-finite value in the domain of metric '" + id_ + "'");
    total += partial[i];
  }
  size_t samples = 0;
  for (size_t n : count) samples += n;
  if (samples == 0) throw MetricUndefined(data_->path(), "no measured value in the domain of metric '" + id_ + "'");
  return finish(scale_ * scale_ * total);
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
  if (auto kept = detail::find_cached_albedo(data, coarsen)) return *kept;
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
    lookup_row(data, wi, wo, m);
    Rgb a = Rgb::Zero();
    for (size_t k = 0; k < wo.size(); ++k)
      if (m[k] && m[k]->allFinite()) a += *m[k] * w[k];  // ρ cosθo dωo
    best[i] = a.maxCoeff();
  });
  double out = 0;
  for (double b : best) out = std::max(out, b);
  detail::keep_albedo(data, coarsen, out);
  return out;
}

}  // namespace brdfkit::fit
