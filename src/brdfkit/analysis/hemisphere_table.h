#pragma once
// A microfacet distribution tabulated over the hemisphere of half vectors (θ, φ), the anisotropic
// table of seed 002 §5.1 (after Ashikhmin et al. 2000: "an arbitrary tabulated representation").
//
// Nodes: the pole, then rings θ_j = (j/(nθ−1))² π/2 (dense near the normal, as MERL's θh axis and
// the isotropic estimate), each with nφ azimuths φ_k = 2πk/nφ. D is bilinear in (θ, φ) between
// nodes (periodic in φ; the pole is one node shared by the first cell of every azimuth), so D is
// linear in the node values, and so are ∫ D cosθ dω (normalization) and the projected area
//   σ(ω) = ∫ max(0, ω·m) D(m) dωm = cosθ / G1(ω)
// (the Smith masking of Heitz 2014 Eq. 2, Ashikhmin et al.'s g(k)): both by a 6 × 6 Gauss-Legendre
// rule on every cell, its points and their stencils found once (σ's kink along ω·m = 0 crosses
// cells, so σ converges more slowly than the normalization).
#include <array>
#include <vector>

#include "brdfkit/core/vec.h"

namespace brdfkit::analysis {

class HemisphereTable {
 public:
  // nθ ≥ 3 rings counting the pole, nφ ≥ 4 azimuths.
  HemisphereTable(int n_theta, int n_phi);

  int n_theta() const { return n_theta_; }
  int n_phi() const { return n_phi_; }
  int nodes() const { return 1 + (n_theta_ - 1) * n_phi_; }
  int node(int j, int k) const;  // ring j, azimuth k (any integer: periodic); the pole for j = 0
  double theta(int j) const { return theta_[size_t(j)]; }
  double phi(int k) const;

  // D(h) = Σ weight · D[node] over at most four nodes; h a unit vector with h_z > 0.
  struct Stencil {
    std::array<int, 4> node{};
    std::array<double, 4> weight{};
    int count = 0;
    double apply(const std::vector<double>& d) const {  // Σ weight · d[node]
      double v = 0;
      for (int q = 0; q < count; ++q) v += weight[size_t(q)] * d[size_t(node[size_t(q)])];
      return v;
    }
  };
  Stencil locate(const Vec3d& h) const;
  double eval(const std::vector<double>& d, const Vec3d& h) const;

  // ∫ D cosθ dω for the node values d (exact for the bilinear D).
  double mass(const std::vector<double>& d) const;
  // Neighbour triples (a, b, c) whose second difference d_a − 2 d_b + d_c measures roughness: along
  // every azimuth's θ column (through the pole) and around every ring.
  std::vector<std::array<int, 3>> second_differences() const;

  // σ(ω) of the node values d on a grid of ω (2° in θ up to 90°, nφ azimuths), interpolated
  // bilinearly; G1(ω) = cosθ / max(cosθ, σ(ω)).
  class Masking {
   public:
    double g1(const Vec3d& w) const;
    double projected_area(const Vec3d& w) const;

   private:
    friend class HemisphereTable;
    int n_theta = 0, n_phi = 0;
    std::vector<double> area;  // [θ index][φ index]
  };
  Masking masking(const std::vector<double>& d) const;

 private:
  int n_theta_, n_phi_;
  std::vector<double> theta_;
  std::vector<double> mass_weight_;  // ∫ basis_n cosθ dω per node
  // Quadrature points over the whole hemisphere: direction, the stencil of D there, dω weight.
  struct Point {
    Vec3d m;
    Stencil stencil;
    double weight;
  };
  std::vector<Point> points_;
};

}  // namespace brdfkit::analysis
