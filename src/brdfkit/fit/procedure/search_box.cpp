#include "brdfkit/fit/procedure/search_box.h"

#include <fmt/format.h>

#include <algorithm>

#include "brdfkit/core/error.h"

namespace brdfkit::fit {

ParamTable with_search_bounds(const Model& inner, const SearchBounds& bounds) {
  ParamTable table = inner.params();
  for (const auto& [name, box] : bounds) {
    const int i = find_param(table, name);
    if (i < 0) continue;
    ParamSpec& s = table[size_t(i)];
    const auto [lo, hi] = box;
    if (!s.in_domain(lo) || !s.in_domain(hi))
      throw SettingError("bounds", fmt::format("{} of {}: [{}, {}] leaves the formula's domain [{}, {}]", name,
                                               inner.name(), lo, hi, s.valid_lower(), s.valid_upper()));
    // The domain is read before the box moves: an unset domain edge is the default box's edge.
    s.domain_lower = s.valid_lower();
    s.domain_upper = s.valid_upper();
    s.lower = lo;
    s.upper = hi;
    s.def = std::clamp(s.def, lo, hi);
  }
  return table;
}

void check_search_bounds(std::span<const Model* const> models, const SearchBounds& bounds) {
  for (const auto& [name, box] : bounds) {
    const bool known =
        std::any_of(models.begin(), models.end(), [&](const Model* m) { return find_param(m->params(), name) >= 0; });
    if (!known) {
      std::string names;
      for (const ParamSpec& s : models.empty() ? ParamTable{} : models.front()->params())
        names += (names.empty() ? "" : ", ") + s.name;
      throw SettingError("bounds",
                         models.size() == 1
                             ? fmt::format("{} has no parameter '{}' (it has {})", models.front()->name(), name, names)
                             : fmt::format("no model of the batch has a parameter '{}'", name));
    }
  }
  for (const Model* m : models) with_search_bounds(*m, bounds);
}

}  // namespace brdfkit::fit
