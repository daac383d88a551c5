#include "brdfkit/models/lobe_sum.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <map>

#include "brdfkit/core/error.h"

namespace brdfkit {

namespace {

constexpr int kAlbedoPoints = 16;
constexpr double kUniformShare = 0.02;

// A start moved towards the lower bound, as tests/models/param_sets.h moves shapes: geometric
// (at most a factor 3) where the value and bound are positive, linear otherwise.
double moved_towards_lower(const ParamSpec& s, double x) {
  constexpr double kFraction = 0.35;
  if (x > 0 && s.lower > 0) return x * std::clamp(std::pow(s.lower / x, kFraction), 1.0 / 3.0, 1.0);
  return x + (s.lower - x) * kFraction;
}

// The last selection probabilities computed on this thread: a χ² test or a renderer asks for
// the pdf at many wi with the same wo and parameters, and the estimate costs ~50 evaluations.
struct ProbabilityCache {
  std::uint64_t owner = 0;
  int channel = -1;
  Vec3d wo = Vec3d::Zero();
  std::vector<double> p;
  std::array<double, LobeSum::kMaxComponents> prob{};
};

}  // namespace

std::uint64_t LobeSum::next_id() {
  static std::atomic<std::uint64_t> id{0};
  return ++id;
}

LobeSum::LobeSum(std::vector<const Model*> components) : id_(next_id()) {
  for (size_t j = 0; j < components.size(); ++j) {
    if (j) name_ += '+';
    name_ += components[j]->name();
  }
  const std::string where = "model '" + name_ + "'";
  if (components.size() < 2) throw InputError(where, "a sum needs at least two components");
  if (components.size() > kMaxComponents)
    throw InputError(where, fmt::format("a sum has at most {} components", kMaxComponents));
  bool have_diffuse = false;
  std::map<std::string_view, int> seen;  // repetitions of each model so far
  std::string lobes;
  for (size_t j = 0; j < components.size(); ++j) {
    const Model& m = *components[j];
    const ParamTable& t = m.params();
    if (t.size() > kMaxComponentParams)
      throw InputError(where, fmt::format("component '{}' has more than {} parameters", m.name(), kMaxComponentParams));
    const int repetition = seen[m.name()]++;
    Component comp{&m, {}};
    bool contributes = false;
    for (const ParamSpec& s : t) {
      const bool diffuse = s.name == "kd" && s.scope == Scope::PerChannel;
      if (diffuse && have_diffuse) {
        comp.source.push_back(-1);  // one diffuse term per sum: later kd held at 0
        continue;
      }
      ParamSpec out = s;
      if (diffuse) {
        have_diffuse = true;
        out.doc = fmt::format("{} (the sum's one diffuse term, from component {} '{}')", s.doc, j + 1, m.name());
      } else {
        out.name = fmt::format("{}.{}", j + 1, s.name);
        out.doc = fmt::format("component {} '{}': {}", j + 1, m.name(), s.doc);
        if (!s.linear)
          for (int k = 0; k < repetition; ++k) out.def = moved_towards_lower(s, out.def);
      }
      comp.source.push_back(int(table_.size()));
      table_.push_back(std::move(out));
      contributes = true;
    }
    if (!contributes)
      throw InputError(where, fmt::format("component {} '{}' would be left without parameters (the sum has one "
                                          "diffuse term, the kd of its first component that has one)",
                                          j + 1, m.name()));
    reciprocal_ = reciprocal_ && m.reciprocal();
    lobes += fmt::format("{}{}", j ? " + " : "", m.name());
    components_.push_back(std::move(comp));
  }
  description_ = fmt::format("sum of {} ({} components; one diffuse term kd, parameters of component j prefixed 'j.')",
                             lobes, components_.size());
}

std::unique_ptr<LobeSum> LobeSum::from_name(std::string_view name) {
  std::vector<const Model*> parts;
  size_t start = 0;
  while (true) {
    const size_t plus = name.find('+', start);
    const std::string_view part = name.substr(start, plus == std::string_view::npos ? std::string_view::npos : plus - start);
    if (part.empty())
      throw InputError("model '" + std::string(name) + "'", "empty component in a sum (expected a+b+…)");
    try {
      parts.push_back(&model_by_name(part));
    } catch (const InputError& e) {
      throw InputError("model '" + std::string(name) + "'", std::string("component: ") + e.what());
    }
    if (plus == std::string_view::npos) break;
    start = plus + 1;
  }
  return std::make_unique<LobeSum>(std::move(parts));
}

void LobeSum::component_params(size_t j, const double* p, double* out) const {
  const std::vector<int>& src = components_[j].source;
  for (size_t i = 0; i < src.size(); ++i) out[i] = src[i] >= 0 ? p[src[i]] : 0.0;
}

double LobeSum::eval(const double* p, int c, const Vec3d& wi, const Vec3d& wo) const {
  std::array<double, kMaxComponentParams> q;
  double sum = 0;
  for (size_t j = 0; j < components_.size(); ++j) {
    component_params(j, p, q.data());
    sum += components_[j].model->eval(q.data(), c, wi, wo);  // DESIGN.md §6: any sum of lobes
  }
  return sum;
}

std::array<double, LobeSum::kMaxComponents> LobeSum::compute_probabilities(const double* p, int c,
                                                                           const Vec3d& wo) const {
  // Albedo a_j(wo) = ∫ ρ_j(wi, wo) cosθi dωi estimated with the component's own sampler at fixed
  // points (an importance-sampled quadrature), seed 004 §5.5's weights.
  std::array<double, kMaxComponents> est{};
  std::array<double, kMaxComponentParams> q;
  const size_t K = components_.size();
  double total = 0;
  for (size_t j = 0; j < K; ++j) {
    component_params(j, p, q.data());
    const Model& m = *components_[j].model;
    double acc = 0;
    for (int k = 0; k < kAlbedoPoints; ++k) {
      // A rank-1 lattice in (u, u_lobe): stratified, deterministic.
      const double g1 = 0.6180339887498949, g2 = 0.7548776662466927;
      const Vec2d u((k + 0.5) / kAlbedoPoints, std::fmod(0.5 + k * g1, 1.0));
      const double ul = std::fmod(0.5 + k * g2, 1.0);
      const auto wi = m.sample(q.data(), c, wo, u, ul);
      if (!wi) continue;
      const double pdf = m.pdf(q.data(), c, wo, *wi);
      const double f = m.eval(q.data(), c, *wi, wo);
      const double x = f * wi->z() / pdf;
      if (pdf > 0 && std::isfinite(x) && x > 0) acc += x;
    }
    est[j] = acc / kAlbedoPoints;
    total += est[j];
  }
  std::array<double, kMaxComponents> prob{};
  for (size_t j = 0; j < K; ++j)
    prob[j] = total > 0 ? (1 - kUniformShare) * est[j] / total + kUniformShare / double(K) : 1.0 / double(K);
  return prob;
}

std::array<double, LobeSum::kMaxComponents> LobeSum::selection_probabilities(const double* p, int c,
                                                                             const Vec3d& wo) const {
  thread_local ProbabilityCache cache;
  const std::uint64_t id = id_;
  const size_t n = table_.size();
  if (cache.owner == id && cache.channel == c && cache.wo == wo && std::equal(p, p + n, cache.p.begin(), cache.p.end()))
    return cache.prob;
  cache.prob = compute_probabilities(p, c, wo);
  cache.owner = id;
  cache.channel = c;
  cache.wo = wo;
  cache.p.assign(p, p + n);
  return cache.prob;
}

std::optional<Vec3d> LobeSum::sample(const double* p, int c, const Vec3d& wo, const Vec2d& u, double u_lobe) const {
  if (!(wo.z() > 0)) return std::nullopt;
  const auto prob = selection_probabilities(p, c, wo);
  const size_t K = components_.size();
  size_t j = 0;
  double acc = 0;
  for (; j + 1 < K; ++j) {
    if (u_lobe < acc + prob[j]) break;
    acc += prob[j];
  }
  // The rest of u_lobe, rescaled to [0, 1), picks the lobe inside the component.
  const double rest = prob[j] > 0 ? std::clamp((u_lobe - acc) / prob[j], 0.0, 1.0 - 1e-16) : 0.0;
  std::array<double, kMaxComponentParams> q;
  component_params(j, p, q.data());
  return components_[j].model->sample(q.data(), c, wo, u, rest);
}

double LobeSum::pdf(const double* p, int c, const Vec3d& wo, const Vec3d& wi) const {
  if (!(wo.z() > 0 && wi.z() > 0)) return 0.0;
  const auto prob = selection_probabilities(p, c, wo);
  std::array<double, kMaxComponentParams> q;
  double sum = 0;
  for (size_t j = 0; j < components_.size(); ++j) {
    component_params(j, p, q.data());
    sum += prob[j] * components_[j].model->pdf(q.data(), c, wo, wi);  // mixture density, lobe_mixture.h
  }
  return sum;
}

}  // namespace brdfkit
