#include "brdfkit/ndf/d_block.h"

#include <cmath>

#include "brdfkit/core/vec.h"
#include "brdfkit/core/vector_kernel.h"

namespace brdfkit {
namespace {

// The block's cosines clamped to [0, 1], so that no lane calls acos or log outside its domain.
inline double unit_interval(double c) { return c > 1.0 ? 1.0 : (c > 0.0 ? c : 0.0); }

}  // namespace

BRDFKIT_VECTOR_KERNEL void gaussian_d_block(double norm, double m, const double* __restrict c,
                                            double* __restrict out) {
  for (std::size_t k = 0; k < kDBlock; ++k) {
    const double theta = acos(unit_interval(c[k]));
    const double d = norm * exp(-theta * theta / (m * m));  // seed 001 Table 1
    out[k] = c[k] > 0.0 ? d : 0.0;
  }
}

BRDFKIT_VECTOR_KERNEL void gtr_d_block(double norm, double alpha, double gamma, const double* __restrict c,
                                       double* __restrict out) {
  for (std::size_t k = 0; k < kDBlock; ++k) {
    const double x = c[k];
    const double s = alpha * alpha * x * x + (1.0 - x) * (1.0 + x);
    const double d = norm / pow(s, gamma);  // Burley 2012, seed 004 Table 1
    out[k] = x > 0.0 ? d : 0.0;
  }
}

BRDFKIT_VECTOR_KERNEL void gaussian_p22_block(double norm, double m, const double* __restrict x,
                                              double* __restrict out) {
  for (std::size_t k = 0; k < kP22Block; ++k) {
    const double c2 = 1.0 / (1.0 + x[k]), c = sqrt(c2);
    const double theta = acos(unit_interval(c));
    const double d = norm * exp(-theta * theta / (m * m));  // seed 001 Table 1
    out[k] = (c > 0.0 ? d : 0.0) * c2 * c2;
  }
}

BRDFKIT_VECTOR_KERNEL void gtr_p22_block(double norm, double alpha, double gamma, const double* __restrict x,
                                         double* __restrict out) {
  for (std::size_t k = 0; k < kP22Block; ++k) {
    const double c2 = 1.0 / (1.0 + x[k]), c = sqrt(c2);
    const double s = alpha * alpha * c * c + (1.0 - c) * (1.0 + c);
    // s^−γ as exp(−γ ln s): libmvec's pow costs more than its exp and log together (a Cornell
    // file's GTR fit, all table nodes, took 13 % longer with pow); both agree to ~γ|ln s|·ε.
    const double d = norm * exp(-gamma * log(s));  // Burley 2012, seed 004 Table 1
    out[k] = (c > 0.0 ? d : 0.0) * c2 * c2;
  }
}

BRDFKIT_VECTOR_KERNEL void sgd_p22_block(double K, double alpha, double p, const double* __restrict x,
                                         double* __restrict out) {
  for (std::size_t k = 0; k < kP22Block; ++k) {
    const double t = alpha + x[k] / alpha;
    out[k] = K * exp(-t - p * log(t)) / kPi;  // seed 000 §4.2
  }
}

BRDFKIT_VECTOR_KERNEL void sgd_d_block(double K, double alpha, double p, const double* __restrict c,
                                       double* __restrict out) {
  for (std::size_t k = 0; k < kDBlock; ++k) {
    const double x = unit_interval(c[k]);
    const double c2 = x * x;
    const double t = alpha + (1.0 - c2) / c2 / alpha;
    const double d = K * exp(-t - p * log(t)) / kPi / (c2 * c2);  // seed 000 §4.2
    out[k] = c[k] > 0.0 ? d : 0.0;
  }
}

BRDFKIT_VECTOR_KERNEL void blinn_phong_d_block(double N, const double* __restrict c, double* __restrict out) {
  for (std::size_t k = 0; k < kDBlock; ++k) {
    const double d = (N + 2.0) / (2 * kPi) * pow(unit_interval(c[k]), N);  // seed 001 Table 1
    out[k] = c[k] > 0.0 ? d : 0.0;
  }
}

BRDFKIT_VECTOR_KERNEL void beckmann_d_block(double alpha, const double* __restrict c, double* __restrict out) {
  const double a2 = alpha * alpha;
  for (std::size_t k = 0; k < kDBlock; ++k) {
    const double x = unit_interval(c[k]);
    const double c2 = x * x;
    const double d = exp(-((1.0 - c2) / c2) / a2) / (kPi * a2) / (c2 * c2);  // seed 000 Table 1
    out[k] = c[k] > 0.0 ? d : 0.0;
  }
}

BRDFKIT_VECTOR_KERNEL void exponential_d_block(double alpha, const double* __restrict c, double* __restrict out) {
  for (std::size_t k = 0; k < kDBlock; ++k) {
    const double x = unit_interval(c[k]);
    const double c2 = x * x;
    const double slope2 = (1.0 - c2) / c2;
    const double e = slope2 > 0.0 ? std::sqrt(slope2) / alpha : 0.0;
    const double d = exp(-e) / (2 * kPi * alpha * alpha) / (c2 * c2);  // seed 000 Table 1
    out[k] = c[k] > 0.0 ? d : 0.0;
  }
}

BRDFKIT_VECTOR_KERNEL void exponential_power_d_block(double norm, double sigma, double p, const double* __restrict c,
                                                     double* __restrict out) {
  for (std::size_t k = 0; k < kDBlock; ++k) {
    const double x = unit_interval(c[k]);
    const double c2 = x * x;
    const double slope2 = (1.0 - c2) / c2;
    const double e = slope2 > 0.0 ? pow(slope2 / (sigma * sigma), p) : 0.0;
    const double d = norm * exp(-e) / (c2 * c2);  // seed 004 Eq. 19
    out[k] = c[k] > 0.0 ? d : 0.0;
  }
}

BRDFKIT_VECTOR_KERNEL void exponential_power_p22_block(double norm, double sigma, double p, const double* __restrict x,
                                                       double* __restrict out) {
  for (std::size_t k = 0; k < kP22Block; ++k) {
    const double y = x[k] / (sigma * sigma);
    // y^p as exp(p ln y), as gtr_p22_block: libmvec's pow costs more than its exp and log together.
    const double e = y > 0.0 ? exp(p * log(y > 0.0 ? y : 1.0)) : 0.0;
    out[k] = norm * exp(-e);  // seed 004 Eq. 19
  }
}

}  // namespace brdfkit
