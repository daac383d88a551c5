#pragma once
// A model whose search box is the user's (FitSettings::bounds) where the user gave one: the same
// formula, parameters and layout, so a fit of it is a fit of the inner model. A box may be wider
// than the default one but stays inside the formula's domain (ParamSpec::valid_lower/upper); a box
// of one point holds the parameter there.
#include <span>

#include "brdfkit/fit/settings/fit_settings.h"
#include "brdfkit/models/model.h"
#include "brdfkit/models/paired_evaluation.h"

namespace brdfkit::fit {

// `inner`'s table with the boxes of `bounds` it has a parameter for applied (defaults clamped into
// their new box): in a batch, a bound applies to the models that have the parameter. SettingError
// ("bounds") for a box outside the formula's domain.
ParamTable with_search_bounds(const Model& inner, const SearchBounds& bounds);
// SettingError ("bounds") unless every bound names a parameter of at least one of `models` and
// lies inside its domain in each of them: what a fit or batch checks before any work.
void check_search_bounds(std::span<const Model* const> models, const SearchBounds& bounds);

class SearchBox final : public Model, public PairedEvaluation {
 public:
  SearchBox(const Model& inner, const SearchBounds& bounds)
      : inner_(inner),
        paired_(dynamic_cast<const PairedEvaluation*>(&inner)),
        table_(with_search_bounds(inner, bounds)) {}
  std::string_view name() const override { return inner_.name(); }
  std::string_view description() const override { return inner_.description(); }
  const ParamTable& params() const override { return table_; }
  bool reciprocal() const override { return inner_.reciprocal(); }
  double eval(const double* p, int c, const Vec3d& wi, const Vec3d& wo) const override {
    return inner_.eval(p, c, wi, wo);
  }
  void eval_batch(const double* p, int c, std::size_t n, const SoaPairs& d, double* out) const override {
    inner_.eval_batch(p, c, n, d, out);
  }
  bool eval_batch_pair(const double* p, int c, int param, double a, double b, std::size_t n, const SoaPairs& d,
                       double* out_a, double* out_b) const override {
    return paired_ && paired_->eval_batch_pair(p, c, param, a, b, n, d, out_a, out_b);
  }
  std::optional<Vec3d> sample(const double* p, int c, const Vec3d& wo, const Vec2d& u, double u_lobe) const override {
    return inner_.sample(p, c, wo, u, u_lobe);
  }
  double pdf(const double* p, int c, const Vec3d& wo, const Vec3d& wi) const override {
    return inner_.pdf(p, c, wo, wi);
  }

 private:
  const Model& inner_;
  const PairedEvaluation* paired_;
  ParamTable table_;
};

}  // namespace brdfkit::fit
