#pragma once
// The user's search boxes (FitSettings::bounds) as a model's table, for a RetabledModel. A box may
// be wider than the default one but stays inside the formula's domain (ParamSpec::valid_lower/upper);
// a box of one point holds the parameter there.
#include <span>

#include "brdfkit/fit/settings/fit_settings.h"
#include "brdfkit/models/model.h"

namespace brdfkit::fit {

// `inner`'s table with the boxes of `bounds` it has a parameter for applied (defaults clamped into
// their new box): in a batch, a bound applies to the models that have the parameter. SettingError
// ("bounds") for a box outside the formula's domain.
ParamTable with_search_bounds(const Model& inner, const SearchBounds& bounds);
// SettingError ("bounds") unless every bound names a parameter of at least one of `models` and
// lies inside its domain in each of them: what a fit or batch checks before any work.
void check_search_bounds(std::span<const Model* const> models, const SearchBounds& bounds);

}  // namespace brdfkit::fit
