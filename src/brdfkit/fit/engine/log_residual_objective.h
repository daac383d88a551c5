#pragma once
// The objective for a residual not linear in ρ (low-e2's ln(1 + ·), seed 003 Eq. 32). The colours
// cannot be projected out, so they stay solver variables (seed 003 §5.1 fits every parameter of E2
// at once), but ρ is still linear in them: ρ_c = Σ_j β_cj b_j(s), b_j the model with colour j = 1
// and the others 0 at the shape s. So the model is evaluated only for the bases (once for R, G and
// B when it ignores the channel; a basis that no shape variable moves, like Lambert's 1/π, once per
// stride), the colour columns of the Jacobian are exact (∂r/∂β_cj = r′ b_j with
// r′ = rw f T′(f ρ)), and only the shape columns take forward differences, of the bases:
// ∂r/∂s_v = r′ Σ_j β_cj ∂b_j/∂s_v. T(f m) is computed once per stride.
#include <array>
#include <vector>

#include "brdfkit/fit/engine/linear_structure.h"
#include "brdfkit/fit/engine/objective.h"

namespace brdfkit::fit {

class LogResidualObjective final : public Objective {
 public:
  // colours: the model's colour parameters (linear_structure.h), solver variables here.
  LogResidualObjective(const FitContext& ctx, const std::vector<int>& colours);
  void reset(bool new_blocks) override;
  bool evaluate(const double* x, bool derivatives, ObjectiveValue& out, ParamValues& values) override;
  // A start's colours: the best ones for its shape under the residual linearized about the data,
  // T(f ρ) − T(f m) ≈ T′(f m) f (ρ − m) (a weighted bound-constrained linear solve per channel).
  void start_colours(ParamValues& pv) override;

 private:
  std::size_t classes_at(const ParamValues& pv) const;
  void prepare_bases(const ParamValues& pv, std::size_t Q);
  std::vector<double> basis_at(const ParamValues& pv, int c, std::size_t j) const {
    return basis_params(pv, c, bases_, j);
  }
  void block_partials(std::size_t i, std::size_t Q, const std::vector<ParamValues>& shifted,
                      const std::vector<double>& h, const std::array<std::vector<double>, 3>& beta,
                      const std::array<std::vector<int>, 3>& cols, const std::array<std::vector<std::size_t>, 3>& shape_of,
                      bool derivatives, double* partial) const;

  const FitContext& ctx_;
  std::vector<LinearBasis> bases_;            // one per colour: basis j has colour j = 1
  std::array<std::vector<int>, 3> var_of_;    // solver variable of colour j in channel c (−1: fixed)
  std::vector<std::size_t> shape_;            // solver variables that are not colours
  bool channel_free_ = false;                 // the bases may be shared by R, G and B
  std::vector<bool> constant_;                // basis j does not depend on the shape
  std::vector<std::vector<double>> keys_;     // [q·K + j]: the parameters bases_values_ holds
  std::vector<std::vector<std::vector<double>>> values_;  // [block][q·K + j][sample]
  std::vector<std::vector<double>> tm_;       // [block][c·n + k] = T(f m_c)
};

}  // namespace brdfkit::fit
