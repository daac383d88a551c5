#include "brdfkit/core/param.h"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "brdfkit/core/error.h"

namespace brdfkit {

double ParamSpec::valid_lower() const { return std::isnan(domain_lower) ? lower : domain_lower; }

double ParamSpec::valid_upper() const {
  if (!std::isnan(domain_upper)) return domain_upper;
  return linear && lower == 0 ? std::numeric_limits<double>::infinity() : upper;
}

ParamValues ParamValues::defaults(const ParamTable& table) {
  ParamValues v;
  for (auto& ch : v.values) {
    ch.reserve(table.size());
    for (const auto& p : table) ch.push_back(p.def);
  }
  return v;
}

int find_param(const ParamTable& table, const std::string& name) {
  for (size_t i = 0; i < table.size(); ++i)
    if (table[i].name == name) return int(i);
  return -1;
}

void ParamValues::set(const ParamTable& table, const std::string& name, double value, int channel) {
  const int i = find_param(table, name);
  if (i < 0) throw InputError("parameter '" + name + "'", "unknown for this model");
  const ParamSpec& p = table[size_t(i)];
  if (!p.in_domain(value))
    throw InputError("parameter '" + name + "'", fmt::format("value {} outside the formula's domain [{}, {}]", value,
                                                             p.valid_lower(), p.valid_upper()));
  if (channel >= 0 && p.scope == Scope::Shared)
    throw InputError("parameter '" + name + "'", "is shared by the three channels; set it without a channel");
  for (int c = 0; c < 3; ++c)
    if (channel < 0 || channel == c) values[size_t(c)][size_t(i)] = value;
}

}  // namespace brdfkit
