#pragma once
// Smith masking G1 of any isotropic distribution given only as D(θm), through the projected-area
// identity cosθ = G1(θ) ∫ ⟨ω·m⟩ D(m) dm (Heitz 2014, "Understanding the masking-shadowing
// function", Eq. 2 and §5.1: Smith's Λ satisfies it for every D), i.e.
//   1 + Λ(θ) = (1/cosθ) ∫ max(0, ω·m) D(m) dωm.
// This is Ashikhmin et al. 2000's g(k) = ⟨k·h⟩, the shadowing term of seed 002 Eq. 3, and needs
// one 1-D integral per angle instead of the nested P2/Λ integrals of DESIGN.md §4, which suits a
// distribution that changes at every iteration of the tabulated-NDF estimation (seed 002 §5.1).
#include <functional>
#include <vector>

namespace brdfkit::analysis {

// The projected area A(θ) = ∫ max(0, ω·m) D(m) dωm = cosθ (1 + Λ(θ)) tabulated over θ ∈ [0, π/2]
// and interpolated linearly in θ; G1 = cosθ / max(cosθ, A) with cosθ exact. Tabulating G1 itself
// failed near the horizon: G1 → 0 there like 2 cosθ/α (GGX), concave in θ, so linear interpolation
// on 0.5° steps was 3.5 % low at 89.9° (α = 0.2), while A is bounded and smooth up to π/2
// (A(π/2) = the mean projected slope area) and its interpolation error stays relative ≈ 4e-4.
// The tabulated-NDF estimation fits cells with θo up to 89.75° at full weight (ngan weighs by cosθi
// only, and ρ stays finite there since G1/cosθo does), so that 3.5 % moved D by 1 %.
class ProjectedAreaMasking {
 public:
  ProjectedAreaMasking() = default;
  // d(cos θm) = D at the microfacet angle, normalized (∫ D cosθ dω = 1). `kinks` are angles where
  // D is not smooth (table nodes): the quadrature panels break there. `nodes` angles in [0, π/2].
  ProjectedAreaMasking(const std::function<double(double cos_theta_m)>& d, const std::vector<double>& kinks,
                       int nodes = 181);
  double g1(double cos_theta) const;
  double lambda(double cos_theta) const;  // 1/G1 − 1

 private:
  std::vector<double> area_;  // A at θ_k = k/(n−1) · π/2 (header comment: why A and not G1 or Λ)
};

}  // namespace brdfkit::analysis
