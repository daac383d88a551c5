#pragma once
// The directional-diffuse series of He, Torrance, Sillion & Greenberg 1991 (Eq. 78):
//   Σ_{m≥1} t_m,   t_m = e^{−g} gᵐ/(m!·m) · exp(−c/m),   c = τ² v_xy²/4,
// summed with a rigorous bound on what it leaves out.
//
// The first term is formed in log space, log t_m = −g + m ln g − ln m! − ln m − c/m, because for
// rough surfaces (g in the hundreds) e^{−g} underflows while gᵐ/m! overflows; doubles then walk by
// term ratios, Jets form every term in log space.
//
// Truncation rule (why it is safe): the summation starts near the peak of t_m and walks outwards
// in both directions. Going up, the ratio r_m = t_{m+1}/t_m = g m/(m+1)² · e^{c/(m(m+1))}
// decreases with m, so once r_M < 1 every omitted term is below t_M r_Mʲ and the whole tail is
// ≤ t_M r_M/(1 − r_M). Going down, ρ_j = t_{j−1}/t_j = j²/(g (j−1)) · e^{−c/(j(j−1))} increases
// with j (both factors do, for j ≥ 2), so ρ_j ≤ ρ_m for 2 ≤ j ≤ m and once ρ_m < 1 the head below
// m is ≤ t_m ρ_m/(1 − ρ_m). Each walk stops when its bound is ≤ rel_tol/2 of the partial sum; the
// omitted part is then ≤ rel_tol of the sum (this is stricter than Radiance's He.cal, which stops
// when one term is < 10⁻⁶: DESIGN.md §6). The bound is reported so tests can compare it with the
// error actually made.
//
// Where the peak is: for c ≪ g² at the Poisson mode m ≈ g; far from the specular peak (c ≫ g²)
// e^{−c/m} moves it to much larger m, and starting at g would walk all the way up to it.
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "brdfkit/core/scalar_chain.h"

namespace brdfkit {

struct HeSeriesStats {
  int terms = 0;              // terms summed
  double omitted_bound = 0;   // upper bound on Σ of the omitted terms, relative to the sum
};

namespace he_detail {

inline constexpr int kMaxTerms = 1000000;  // never reached for g within the model's bounds (g < 10⁴)

// The sum so far and the bounds on what each walk has left out.
template <class T> struct Walk {
  T sum;
  int terms = 1;
  double up_bound = std::numeric_limits<double>::infinity(), down_bound = 0;
};

// r_j = t_{j+1}/t_j = g j/(j+1)² · e^{c/(j(j+1))} at j = j0, j0 + step, …: kRatioBlock of them from
// glibc's vector exp (he_series_ratios.cpp, within 4 ulp of the scalar exp). A j below 1 (past
// the end of a downward walk, never read) is taken as 1.
inline constexpr int kRatioBlock = 8;
void term_ratios(double g, double c, int j0, int step, double* r);

// The ratios r_j a walk meets, in its order, computed a block at a time.
class RatioStream {
 public:
  RatioStream(double g, double c, int j, int step) : g_(g), c_(c), j_(j), step_(step) {}
  double next() {
    if (k_ == kRatioBlock) {
      term_ratios(g_, c_, j_, step_, r_);
      j_ += step_ * kRatioBlock;
      k_ = 0;
    }
    return r_[k_++];
  }

 private:
  double g_, c_;
  int j_, step_, k_ = kRatioBlock;
  double r_[kRatioBlock];
};

// Doubles walk by the term ratios (an exp per term, eight at a time, instead of lgamma, log and
// exp): the product of ≤ a few hundred ratios is exact to ~1e-13, far inside rel_tol. Every term
// is ≤ 1, so from a normal first term no ratio overflows.
inline void walk_by_ratios(double g, double c, int start, double rel_tol, Walk<double>& w) {
  const double first = w.sum;
  double t = first;
  RatioStream up(g, c, start, 1);
  for (int m = start; w.terms < kMaxTerms; ++m) {
    const double r = up.next();  // r_m = t_{m+1}/t_m
    if (r < 1) {
      w.up_bound = t * r / (1 - r);
      if (w.up_bound <= 0.5 * rel_tol * w.sum) break;
    }
    t *= r;
    w.sum += t;
    ++w.terms;
  }
  t = first;
  RatioStream down(g, c, start - 1, -1);
  for (int m = start; m > 1 && w.terms < kMaxTerms; --m) {
    const double rho = 1 / down.next();  // ρ_m = t_{m−1}/t_m = 1/r_{m−1} ≥ ρ_j, j ≤ m
    if (rho < 1) {
      w.down_bound = t * rho / (1 - rho);
      if (w.down_bound <= 0.5 * rel_tol * w.sum) break;
    }
    t *= rho;
    w.sum += t;
    ++w.terms;
    w.down_bound = 0;  // reaching m = 1 leaves nothing below
  }
}

// log t_m, given log g.
template <class T> T log_term(const T& g, const T& log_g, const T& c, int m) {
  return -g + double(m) * log_g - std::lgamma(m + 1.0) - std::log(double(m)) - c / double(m);
}

// Every term in log space, for Jets (doubles walk by ratios, he_series).
template <class T> void walk_by_logs(const T& g, const T& c, int start, double rel_tol, Walk<T>& w) {
  using std::exp;
  using std::log;
  const T log_g = log(g);
  const double lgv = std::log(value_of(g)), cv = value_of(c);
  // log r_m (up) and log ρ_m (down), in doubles: they only steer the walk.
  auto log_up_ratio = [&](int m) { return lgv + std::log(double(m)) - 2 * std::log(m + 1.0) + cv / (double(m) * (m + 1.0)); };
  auto log_down_ratio = [&](int m) { return 2 * std::log(double(m)) - lgv - std::log(m - 1.0) - cv / (double(m) * (m - 1.0)); };
  // Geometric tail t·r/(1 − r) for log r < 0.
  auto tail = [](double t, double log_r) { const double r = std::exp(log_r); return t * r / (1 - r); };
  const T first = w.sum;
  T t = first;
  for (int m = start; w.terms < kMaxTerms; ++m) {
    const double lr = log_up_ratio(m);
    if (lr < 0) {
      w.up_bound = tail(value_of(t), lr);
      if (w.up_bound <= 0.5 * rel_tol * value_of(w.sum)) break;
    }
    t = exp(log_term(g, log_g, c, m + 1));
    w.sum += t;
    ++w.terms;
  }
  t = first;
  for (int m = start; m > 1 && w.terms < kMaxTerms; --m) {
    const double lq = log_down_ratio(m);
    if (lq < 0) {
      w.down_bound = tail(value_of(t), lq);
      if (w.down_bound <= 0.5 * rel_tol * value_of(w.sum)) break;
    }
    t = exp(log_term(g, log_g, c, m - 1));
    w.sum += t;
    ++w.terms;
    w.down_bound = 0;
  }
}

// The index nearest the peak of t_m. With Stirling's ln m! and O(1/m) dropped, d/dm ln t_m is
// F(u) = ln g − u + c e^{−2u} in u = ln m: decreasing and convex, so Newton's method converges to
// its root, from the left monotonically (the first step from the right lands left of it). The
// walks are exact from any start; a close one only saves terms.
inline int peak_index(double g, double c) {
  const double log_g = std::log(g);
  double u = std::max(log_g, 0.5 * std::log(c));  // g, or √c where c ≫ g² (F(√c) = ln g − ln √c + 1)
  for (int i = 0; i < 16; ++i) {
    const double e = c * std::exp(-2 * u);
    const double step = (log_g - u + e) / (1 + 2 * e);
    u += step;
    if (std::fabs(step) < 0.01) break;  // within 1 % of m: a few terms, where the peak is ~√m wide
  }
  return std::max(1, int(std::lround(std::exp(u))));
}

}  // namespace he_detail

// Σ t_m of He et al. 1991 Eq. 78 (without its π²τ²/(4λ²) prefactor), g ≥ 0, c ≥ 0.
// T is double or a ceres::Jet: the walk is steered by the values, the terms carry derivatives.
template <class T> T he_series(const T& g, const T& c, double rel_tol = 1e-6, HeSeriesStats* stats = nullptr) {
  using std::exp;
  using std::log;
  const double gv = value_of(g);
  if (!(gv > 0)) {
    if (stats) *stats = {0, 0.0};
    return T(0);  // a perfectly smooth surface has no directional-diffuse part (He 1991 §4)
  }
  const int start = he_detail::peak_index(gv, value_of(c));
  const T log_first = he_detail::log_term(g, log(g), c, start);
  he_detail::Walk<T> w{exp(log_first)};
  if constexpr (std::is_same_v<T, double>) {
    if (w.sum > 1e-280) {
      he_detail::walk_by_ratios(gv, c, start, rel_tol, w);
    } else {
      // The first term underflows or nearly: the same ratio walk on t_m/t_start (each ≲ 1 from the
      // peak, as in he_log_series), scaled back at the end. The bounds are relative to the sum,
      // so the walk stops where a walk of the terms themselves would; a log walk would pay an
      // exp, a log and an lgamma a term.
      he_detail::Walk<double> r{1.0};
      he_detail::walk_by_ratios(gv, c, start, rel_tol, r);
      if (stats) *stats = {r.terms, (r.up_bound + r.down_bound) / r.sum};
      return std::exp(log_first + std::log(r.sum));
    }
  } else {
    he_detail::walk_by_logs(g, c, start, rel_tol, w);
  }
  if (stats) {
    const double s = value_of(w.sum);
    stats->terms = w.terms;
    stats->omitted_bound = s > 0 ? (w.up_bound + w.down_bound) / s : 0.0;
  }
  return w.sum;
}

// log Σ t_m for g > 0, where the sum may lie below the smallest double: the walk sums t_m/t_start
// (the same ratios and stopping rule as he_series; from the peak every t_m/t_start is ≲ 1, as the
// ratio walk needs) and adds log t_start.
inline double he_log_series(double g, double c, double rel_tol) {
  const int start = he_detail::peak_index(g, c);
  he_detail::Walk<double> w{1.0};
  he_detail::walk_by_ratios(g, c, start, rel_tol, w);
  return he_detail::log_term(g, std::log(g), c, start) + std::log(w.sum);
}

}  // namespace brdfkit
