#include "brdfkit/fit/engine/weighted_dots.h"

#include "brdfkit/core/vector_kernel.h"

namespace brdfkit::fit {

namespace {

// The four partial sums of one term as one vector: lane l holds the samples k ≡ l (mod 4). Vector
// extensions compute lane by lane, the scalar expression to the bit, in whatever registers the
// clone has (two SSE2 halves, one AVX2 register). Read from any double (aligned to 8, may alias).
typedef double Lanes __attribute__((vector_size(4 * sizeof(double))));
typedef double LanesAt __attribute__((vector_size(4 * sizeof(double)), aligned(8), may_alias));
#define LANES_AT(p) (*reinterpret_cast<const LanesAt*>(p))

double finish(const Lanes& s, std::size_t k, std::size_t n, const double* w2, const double* x, const double* y) {
  double s0 = s[0];
  for (std::size_t j = k; j < n; ++j) s0 += w2[j] * x[j] * y[j];
  return (s0 + s[1]) + (s[2] + s[3]);
}

// Four terms in one sweep: four independent chains of additions, w² read once for them.
BRDFKIT_VECTOR_KERNEL void sweep4(std::size_t n, const double* __restrict w2, const DotTerm* terms, double* out) {
  const double *x0 = terms[0].x, *x1 = terms[1].x, *x2 = terms[2].x, *x3 = terms[3].x;
  const double *y0 = terms[0].y, *y1 = terms[1].y, *y2 = terms[2].y, *y3 = terms[3].y;
  Lanes s0 = {}, s1 = {}, s2 = {}, s3 = {};
  std::size_t k = 0;
  for (; k + 4 <= n; k += 4) {
    const Lanes w = LANES_AT(w2 + k);
    s0 += w * LANES_AT(x0 + k) * LANES_AT(y0 + k);
    s1 += w * LANES_AT(x1 + k) * LANES_AT(y1 + k);
    s2 += w * LANES_AT(x2 + k) * LANES_AT(y2 + k);
    s3 += w * LANES_AT(x3 + k) * LANES_AT(y3 + k);
  }
  out[0] = finish(s0, k, n, w2, x0, y0);
  out[1] = finish(s1, k, n, w2, x1, y1);
  out[2] = finish(s2, k, n, w2, x2, y2);
  out[3] = finish(s3, k, n, w2, x3, y3);
}

BRDFKIT_VECTOR_KERNEL double sweep1(std::size_t n, const double* __restrict w2, const double* x, const double* y) {
  Lanes s = {};
  std::size_t k = 0;
  for (; k + 4 <= n; k += 4) s += LANES_AT(w2 + k) * LANES_AT(x + k) * LANES_AT(y + k);
  return finish(s, k, n, w2, x, y);
}

#undef LANES_AT

}  // namespace

void weighted_dots(std::size_t n, const double* w2, std::span<const DotTerm> terms, double* out) {
  std::size_t t = 0;
  for (; t + 4 <= terms.size(); t += 4) sweep4(n, w2, terms.data() + t, out + t);
  for (; t < terms.size(); ++t) out[t] = sweep1(n, w2, terms[t].x, terms[t].y);
}

double weighted_dot(std::size_t n, const double* w2, const double* x, const double* y) { return sweep1(n, w2, x, y); }

}  // namespace brdfkit::fit
