#pragma once
// He et al. 1991's Eq. 78 series S(g, c) = Σ_{m≥1} e^{−g} gᵐ/(m!·m) e^{−c/m} (he_series.h) from a
// table, for the doubles of model evaluation: the series needs ~10 √g terms (one exp each: 62 on
// average over a 2° grid at colodur_napoli's He fit, 78 % of that fit's time), the table one exp.
//
// S depends on nothing but (g, c), so one table serves every parameter set and channel. Its columns
// are x = log g at steps 0.03 over 0.5 ≤ g ≤ 10⁴ (the fitter's box reaches g ≈ 3200); each column
// holds two runs of rows, both in c/g, so that the channels of a pair, which share c/g, share rows:
//  - near, c/g ≤ 1000: r = log S + log g + c/g at y = log(1 + c/g), steps 0.01 (S ≈ e^{−c/g}/g for
//    large g: r is what is left, smooth);
//  - far, 1000 < c/g ≤ 10⁵: r = log S + log g at q = log(c/g), steps 0.01 (the near run's r and y
//    carried on to c/g = 10⁵ interpolate to 1.1e-5 there at these steps, in NumPy).
// Each node is summed to 10⁻¹⁰ in log space (he_log_series: far from the peak of a rough surface S
// lies below the smallest double, r does not); a look-up is the tensor-product cubic Lagrange
// interpolant of the 4 × 4 nodes around it, and S = e^{r − y}/g (y = 0 in the far run). Worst
// relative error against the series over the table's domain, where S is a normal double: 4.4e-7 in
// the near run (at g ≈ 0.51, c/g ≈ 21), 3.7e-7 in the far one (g ≈ 0.64, c/g ≈ 4.4·10⁴; 5.6e-7 at
// steps 0.02 in q) (tests/models/he/test_he_series_table.cpp), inside the 1e-6 to which the series
// itself is summed. Below g = 0.5 this interpolant at these steps passes 1e-6 (1.6e-6 near g ≈ 0.1,
// c/g ≈ 80, against the series summed in NumPy). Down to 0.5 the table serves smooth surfaces too:
// g = (kσ)²(cos θi + cos θo)² ≤ 9 at vch_golden_yellow's He fit (σ0 ≈ 0.11 µm), whose summed series
// took 31 % of its profile with the table from g = 2 (14.5 s of CPU; 7.6–8.4 s with the table from
// g = 0.5).
// c/g reaches (τ/2σ)² (v_xy/v_z)², large away from the specular peak of a smooth, long-correlated
// surface: in cc_ibiza_sunset's fit (τ/2σ ≈ 10) 27 % of look-ups have c/g > 100, and 1 % > 1000; in
// Cornell acryl_blue's (τ/2σ ≈ 80) 69 % have 1000 < c/g ≤ 10⁵ with g ≥ 0.5, the far run's domain:
// summed, the series took 62 % of that fit's profile (1.6 s of CPU; 0.34 s with the far run).
// Below g = 0.5 a third run, the low one, covers 10⁻³ ≤ g < 0.5 with c ≤ 10⁵ g: r = log S − log g + g
// (log Σ g^{m−1}/(m!·m) e^{−c/m}) at x = log g, steps 0.03, and y = log(1 + c), steps 0.01, so
// S = g e^{r − g}. Its rows follow c, not c/g: at small g the series' terms take turns at the lead
// as c grows (term m over m + 1 near c ≈ m² log(m/g), over a width ≈ m² in c), a feature whose width
// is a fixed fraction of c, and in (log g, c/g) each such turn would sweep across the columns, which
// the near run's interpolant missed by 1.6e-6. At the default He parameters 6–10 % of a MERL grid's
// look-ups have g < 0.5; summed, they took a quarter of its evaluation time
// (bench/bench_model_eval.cpp). Worst relative error 2.0e-7, at g ≈ 0.0011, c ≈ 17
// (tests/models/he/test_he_series_table.cpp).
// Outside the domain (g < 10⁻³: few terms, cheap; larger g or c/g) it sums the series.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace brdfkit {

class HeSeriesTable {
 public:
  // The relative error the table keeps to (the series' own truncation, HeTorrance::kSeriesTolerance).
  static constexpr double kRelativeError = 1e-6;
  // Outside its domain S is summed to this, far inside kRelativeError: the fitter differentiates
  // by forward steps of 1e-6 relative (fit/engine/finite_difference.h), and a sum truncated at
  // 1e-6 jumps by up to that much where its term count changes, which makes such a difference
  // wrong by O(1): enough to send vch_golden_yellow's He fit to a minimum 1 % worse.
  static constexpr double kSummedTolerance = 1e-10;
  // The table, whose nodes are compiled in (a function-local static, so thread-safe).
  static const HeSeriesTable& get();

  // The nodes, column by column (x0 + i·step x, i < columns): the near rows r(j·step y), j < rows,
  // then the far rows r(q0 + j·step q), j < far_rows. The build runs compute_nodes once
  // (cmake/generators/he_series_table.cpp) and compiles its output in, so that a process does not
  // sum 390 k series (~0.7 s of CPU) before its first look-up.
  // The low run's nodes follow, column by column: r(j·step y), j < low_rows, in low_columns
  // columns from log kGLow − step x.
  struct Nodes {
    int columns, rows, far_rows;
    std::vector<double> r;
    int low_columns, low_rows;
    std::vector<double> low;
  };
  static Nodes compute_nodes();  // he_series_table_nodes.cpp
  std::span<const double> nodes() const { return {r_, std::size_t(nx_) * std::size_t(stride_)}; }
  std::span<const double> low_nodes() const { return {low_, std::size_t(low_nx_) * std::size_t(low_ny_)}; }

  // S(g, c): from the table inside its domain, else the series summed to kSummedTolerance.
  double operator()(double g, double c) const;
  // Whether (g, c) is read from the table, from any of its runs (& rather than &&: no branches,
  // for lane_sources' vector loop).
  static bool covers(double g, double c) { return (g >= kGLow) & (g <= kGMax) & (c >= 0) & (c <= kRatioMax * g); }

  // The look-ups a batch makes at once.
  static constexpr std::size_t kBlock = 64;
  // S at the kBlock pairs (g[k], c[k]): operator()'s interpolation, its log, log1p and exp taken
  // from glibc's vector math (core/vector_kernel.h, within 4 ulp of the scalar functions; the
  // result within 1e-12 relative of operator() in the near run, 1e-11 in the far one, where log S
  // moves by up to ~700 per unit of q; tests/models/he/test_he_series_table.cpp), and the series
  // summed where the table does not cover the pair. A value depends on its pair alone.
  void block(const double* g, const double* c, double* s) const;

  // The row side of a block's look-ups: the rows are a function of c/g alone, so pairs that share
  // c/g share their row weights, and their log1p or log. He's channels do: g and c both scale with
  // k² = (2π/λ)² (HeTorrance::unsummed_of), c/g = τ² v_xy²/(4 σ² v_z²).
  struct Rows {
    double ratio[kBlock];   // c/g as given (block_at's fallback sums the series at c = ratio · g)
    double y[kBlock];       // S = e^{r − y}/g: c/g clamped into the near run, 0 in the far run
    int j[kBlock];          // the node below, counted from the column's first (far rows follow near)
    double w[4][kBlock];    // lagrange4's weights of the rows j − 1 … j + 2
  };
  // Rows of the kBlock ratios c/g (he_series_block.cpp).
  void rows(const double* ratio, Rows& out) const;
  // S at the kBlock pairs (g[k], ratio[k] · g[k]): block's look-up with the rows given. Within
  // block's bounds of operator() (its c/g an ulp away), summed where the table does not cover.
  void block_at(const Rows& rows, const double* g, double* s) const;

 private:
  static constexpr double kGLow = 1e-3, kGMin = 0.5, kGMax = 1e4;  // the low run below kGMin
  static constexpr double kYMax = 1000, kRatioMax = 1e5;  // c/g ≤ kYMax near, ≤ kRatioMax far
  static constexpr double kStepX = 0.03, kStepY = 0.01, kStepQ = 0.01;
  // Nodes per unit of x, y and q.
  static constexpr double kPerStepX = 1 / kStepX, kPerStepY = 1 / kStepY, kPerStepQ = 1 / kStepQ;

  HeSeriesTable();
  static double first_x() { return std::log(kGMin) - kStepX; }  // x0: see x0_
  static double first_q() { return std::log(kYMax) - kStepQ; }  // q0: one below the far run's domain
  static double first_low_x() { return std::log(kGLow) - kStepX; }
  // Whether the near or far run covers (g, c).
  static bool covers_main(double g, double c) { return (g >= kGMin) & (g <= kGMax) & (c >= 0) & (c <= kRatioMax * g); }

  // The row side of a look-up at c/g = ratio: the node below (from the column's first), the
  // position t ∈ [0, 1] past it, and y of S = e^{r − y}/g. A ratio outside [0, kRatioMax] (a NaN
  // too) is taken at the nearer edge; covers() sends such pairs to the series. Static, its members
  // passed in, and always inlined, as interpolate: so rows()' loop stays a vector loop.
  struct RowAt {
    int j;
    double t, y;
  };
  [[gnu::always_inline]] static RowAt row_at(double ratio, double q0, int near_rows, int far_rows) {
    const double low = ratio > 0 ? ratio : 0;
    const double in = low < kRatioMax ? low : kRatioMax;
    const bool far = in > kYMax;
    // Both coordinates at every ratio, each clamped into its run: a call under a condition would
    // keep the loop scalar too.
    const double fq = (log(far ? in : kYMax) - q0) * kPerStepQ, fy = log1p(far ? kYMax : in) * kPerStepY;
    const double f = far ? fq : fy;
    const int j = std::min(std::max(int(f), 1), (far ? far_rows : near_rows) - 3);
    return {far ? near_rows + j : j, f - j, far ? 0.0 : in};
  }

  // Weights of the cubic Lagrange interpolant through the nodes at −1, 0, 1, 2, at t ∈ [0, 1].
  // (Products with 1/6, not divisions by 6: a division costs several multiplications.)
  static void lagrange4(double t, double w[4]) {
    constexpr double kSixth = 1.0 / 6;
    w[0] = -t * (t - 1) * (t - 2) * kSixth;
    w[1] = (t + 1) * (t - 1) * (t - 2) * 0.5;
    w[2] = -(t + 1) * t * (t - 2) * 0.5;
    w[3] = (t + 1) * t * (t - 1) * kSixth;
  }
  // r at the column coordinate fx = (log g − x0)/step x, given the rows' weights wy around the
  // node j (row_at): the tensor-product cubic through the 4 × 4 nodes around them. operator() and
  // interpolate_block both read it here; always inlined, since a call left in interpolate_block's
  // vector clones keeps their loops scalar.
  [[gnu::always_inline]] static double interpolate(const double* nodes, int nx, int stride, double fx, int j,
                                                   const double* wy, std::size_t wy_step) {
    const int i = std::min(std::max(int(fx), 1), nx - 3);
    double wx[4];
    lagrange4(fx - i, wx);
    const double* column = nodes + std::size_t(i - 1) * std::size_t(stride) + std::size_t(j - 1);
    double r = 0;
    for (int b = 0; b < 4; ++b) {
      double row = 0;
      for (int a = 0; a < 4; ++a) row += wx[a] * column[std::size_t(a) * std::size_t(stride) + std::size_t(b)];
      r += wy[std::size_t(b) * wy_step] * row;
    }
    return r;
  }
  // block_at's interpolation at every lane, each g first clamped into the domain (he_series_block.cpp).
  void interpolate_block(const Rows& rows, const double* g, double* s) const;

  // S from the low run at (g, c) inside it: the cubic through the 4 × 4 nodes around
  // (log g, log(1 + c)), as interpolate. Static and always inlined for low_block's vector loop.
  [[gnu::always_inline]] static double low_at(const double* nodes, int nx, int ny, double x0, double g, double c) {
    const double x = log(g), fy = log1p(c) * kPerStepY;
    const int j = std::min(std::max(int(fy), 1), ny - 3);
    double wy[4];
    lagrange4(fy - j, wy);
    return exp(interpolate(nodes, nx, ny, (x - x0) * kPerStepX, j, wy, 1) - g + x);
  }
  // low_at at the kLowLanes lanes (g[k], c[k]), all inside the low run (he_series_block.cpp): a
  // block's few low-run look-ups (near grazing directions) go through it eight at a time.
  static constexpr std::size_t kLowLanes = 8;
  void low_block(const double* g, const double* c, double* s) const;
  // s[k] at the lanes the main runs do not cover: the low run's where it covers them, else the
  // series summed.
  void fill_uncovered(const double* g, const double* c, double* s) const;
  // Each lane's source, on vector lanes (he_series_block.cpp): kMain (the near or far run), kLow or
  // kSummed; true where some lane is not kMain.
  enum : unsigned char { kMain = 0, kLow = 1, kSummed = 2 };
  static bool lane_sources(const double* g, const double* c, unsigned char* source);

  // x = log g of the first column: one below g = kGMin, so that a look-up inside the domain has
  // its 4 × 4 nodes; q = log(c/g) of the first far row.
  double x0_ = 0, q0_ = 0;
  // Columns, near rows, and nodes per column (near and far rows).
  int nx_ = 0, ny_ = 0, stride_ = 0;
  // Column by column: a batch's pairs mostly share g (a metric's grid varies Δφ fastest, which
  // leaves the cosines unchanged), so a block's look-ups walk along the rows of 4 columns.
  const double* r_ = nullptr;
  // The low run: x = log g of its first column, its columns and rows, its nodes column by column.
  double low_x0_ = 0;
  int low_nx_ = 0, low_ny_ = 0;
  const double* low_ = nullptr;
};

}  // namespace brdfkit
