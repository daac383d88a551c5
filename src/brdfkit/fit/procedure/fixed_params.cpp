#include "brdfkit/fit/procedure/fixed_params.h"

#include <array>

#include "brdfkit/core/error.h"

namespace brdfkit::fit {

namespace {
constexpr size_t kMaxParams = 64;  // a stack buffer per evaluation: no allocation in the fit's loops
}

FixedParams::FixedParams(const Model& inner, const std::vector<bool>& fixed, ParamValues values)
    : inner_(inner), values_(std::move(values)) {
  const ParamTable& t = inner.params();
  if (fixed.size() != t.size() || t.size() > kMaxParams)
    throw InputError("model '" + std::string(inner.name()) + "'", "cannot hold parameters fixed (table size)");
  for (size_t i = 0; i < t.size(); ++i)
    if (!fixed[i]) {
      free_.push_back(int(i));
      table_.push_back(t[i]);
    }
}

template <class F> auto FixedParams::with_full(const double* p, int c, F&& f) const {
  std::array<double, kMaxParams> full;
  const auto& v = values_.values[size_t(c)];
  std::copy(v.begin(), v.end(), full.begin());
  for (size_t k = 0; k < free_.size(); ++k) full[size_t(free_[k])] = p[k];
  return f(full.data());
}

double FixedParams::eval(const double* p, int c, const Vec3d& wi, const Vec3d& wo) const {
  return with_full(p, c, [&](const double* full) { return inner_.eval(full, c, wi, wo); });
}

void FixedParams::eval_batch(const double* p, int c, std::size_t n, const SoaPairs& d, double* out) const {
  with_full(p, c, [&](const double* full) { inner_.eval_batch(full, c, n, d, out); });
}

std::optional<Vec3d> FixedParams::sample(const double* p, int c, const Vec3d& wo, const Vec2d& u,
                                         double u_lobe) const {
  return with_full(p, c, [&](const double* full) { return inner_.sample(full, c, wo, u, u_lobe); });
}

double FixedParams::pdf(const double* p, int c, const Vec3d& wo, const Vec3d& wi) const {
  return with_full(p, c, [&](const double* full) { return inner_.pdf(full, c, wo, wi); });
}

ParamValues FixedParams::merged(const ParamValues& free_values) const {
  ParamValues out = values_;
  for (int c = 0; c < 3; ++c)
    for (size_t k = 0; k < free_.size(); ++k)
      out.values[size_t(c)][size_t(free_[k])] = free_values.values[size_t(c)][k];
  return out;
}

ParamValues FixedParams::free_part(const ParamValues& inner_values) const {
  ParamValues out;
  for (int c = 0; c < 3; ++c)
    for (int i : free_) out.values[size_t(c)].push_back(inner_values.values[size_t(c)][size_t(i)]);
  return out;
}

}  // namespace brdfkit::fit
