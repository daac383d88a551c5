#pragma once
// The variable-projection objective (seed 002 §3) for a residual linear in ρ: the colours (and
// Fresnel-like parameters paired with them, linear_structure.h) are solved inside every
// evaluation; the solver moves only the shape.
//
// With the shape x fixed, ρ_c = Σ_j β_cj b_j(x) and the colours β_c minimize Σ w² (B β − m_c)²:
// everything the solver needs is an inner product <a, b> = Σ_k w_k² a_k b_k of the bases b_j,
// their derivatives d_vj = ∂b_j/∂x_v and the measured m_c. One parallel pass per evaluation
// accumulates those Gram matrices; β = the box-constrained solution of <B,B> β = <B,m>; the
// residual r = Bβ − m has (Golub & Pereyra 1973) the Jacobian J_v = d_v β + B ∂β_v, with ∂β_v
// on the free colours F solving <B,B>_FF ∂β_F = <d_v,m> − (<d_v,B> + <B,d_v>) β (active colours
// stay at their bound), so JᵀJ is a few small products of those Gram blocks. Cost and Jᵀr are
// summed directly from the residuals (no cancellation at a near-zero residual).
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

#include "brdfkit/fit/engine/linear_structure.h"
#include "brdfkit/fit/engine/objective.h"
#include "brdfkit/models/paired_evaluation.h"

namespace brdfkit::fit {

class ProjectedObjective final : public Objective {
 public:
  ProjectedObjective(const FitContext& ctx, std::vector<LinearBasis> bases);
  void reset(bool new_blocks) override;
  bool evaluate(const double* x, bool derivatives, ObjectiveValue& out, ParamValues& values) override;

 private:
  using BlockBases = std::vector<std::vector<std::vector<double>>>;  // [block][q·K + j][sample]
  // The bases at one shape and their Gram matrices.
  struct Gram {
    BlockBases bases;
    std::vector<double> x;
    std::vector<Eigen::MatrixXd> gram;  // <B, B> per class
    std::array<Eigen::VectorXd, 3> ym;  // <B, m_c> per channel
    bool valid = false;
  };
  // The derivative vectors d_vj of class q, laid out after the K bases in an extended Gram
  // matrix E[q] of size L[q] (and <e, m_c> after it) in each block's partial sums.
  struct Extended {
    std::vector<std::vector<std::pair<std::size_t, std::size_t>>> ext;  // (v, j) per extra column
    std::vector<std::size_t> L, offset;
    std::size_t width = 0;  // partial sums per block: cost, Jᵀr (ignoring ∂β), then the E's
  };

  std::size_t classes() const { return std::size_t(classes_); }
  template <class Out>
  void eval_bases(const ParamValues& pv, int q, const SampleBlock& b, const std::vector<std::size_t>& js,
                  Out&& out) const;
  template <class Out>
  void eval_bases_all(const ParamValues& pv, const SampleBlock& b, const std::vector<std::size_t>& js, Out&& out) const;
  void fill_constant_bases();
  const double* basis(std::size_t i, int q, std::size_t j) const;
  void update_gram(const double* x, const ParamValues& pv);
  void gram_partials(std::size_t i, const ParamValues& pv, double* acc);
  bool solve_colours(std::array<Eigen::VectorXd, 3>& beta, Eigen::VectorXd& lo, Eigen::VectorXd& hi) const;
  void write_colours(const std::array<Eigen::VectorXd, 3>& beta, ParamValues& pv) const;
  Extended extended(bool derivatives) const;
  using Derivatives = std::vector<std::vector<double>>;  // d_vj of class q at [(q·nv + v)·K + j]
  template <class Out>
  bool rescale_bases(const ParamValues& at_x, const ParamValues& pv, int q, std::size_t i, Out&& out) const;
  Derivatives derivative_bases(std::size_t i, const ParamValues& at_x, const std::vector<ParamValues>& shifted,
                               const std::vector<double>& h) const;
  void residual_partials(std::size_t i, const std::array<Eigen::VectorXd, 3>& beta, const Derivatives& dv,
                         bool derivatives, double* acc) const;
  void extended_partials(std::size_t i, const Extended& e, const Derivatives& dv, double* acc) const;
  void add_channel_jacobian(int c, const Eigen::VectorXd& bc, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                            const Extended& e, const std::vector<Eigen::MatrixXd>& E,
                            const std::vector<std::array<Eigen::VectorXd, 3>>& Ey, ObjectiveValue& out) const;

  const FitContext& ctx_;
  const PairedEvaluation* paired_;  // the model's paired evaluation, if it offers one
  std::vector<LinearBasis> bases_;
  int classes_ = 3;                // 1 when R, G and B share one basis set
  std::vector<bool> constant_;     // basis j does not depend on the shape
  std::vector<std::size_t> varying_;
  BlockBases constant_bases_;      // the constant bases, once per stride (a class equal to class 0: empty)
  Gram current_;                   // at the last point evaluated
};

}  // namespace brdfkit::fit
