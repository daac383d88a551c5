#include "brdfkit/core/param.h"

#include "brdfkit/core/error.h"

namespace brdfkit {

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
  if (!(value >= p.lower && value <= p.upper))
    throw InputError("parameter '" + name + "'", "value " + std::to_string(value) + " outside [" +
                                                      std::to_string(p.lower) + ", " + std::to_string(p.upper) + "]");
  if (channel >= 0 && p.scope == Scope::Shared)
    throw InputError("parameter '" + name + "'", "is shared by the three channels; set it without a channel");
  for (int c = 0; c < 3; ++c)
    if (channel < 0 || channel == c) values[size_t(c)][size_t(i)] = value;
}

}  // namespace brdfkit
