#pragma once
// D over a fixed-size block of cosθh, for the batch loops (models/cook_torrance.h,
// models/holzschuch_pacanowski.h): the distributions whose D calls acos, exp, log or pow run these
// kernels, which call glibc's vector math (core/vector_kernel.h: AVX-512 or AVX2 where the CPU has
// it, SSE2 otherwise) on kDBlock values at once, where the scalar D would call libm once per value
// (measured in bench/bench_model_eval.cpp).
// Each kernel is the scalar D's expression in the same order; only the libm calls differ, by at
// most 4 ulp each, which an exp of a large argument magnifies: tests/ndf/test_d_block.cpp bounds
// the difference from D by 1e-12 relative. The block is always full (callers pad it), so a value
// depends on its cosine only, never on its position or the block's fill.
#include <cstddef>

namespace brdfkit {

inline constexpr std::size_t kDBlock = 256;
// P22 over a block of slopes x = tan²θ, for the Smith integral (shadowing/smith_integrand_block.h):
// a node's integral has a few hundred values, so its blocks are short.
inline constexpr std::size_t kP22Block = 32;

// Gaussian (ndf/gaussian.h): norm · exp(−θ²/m²), θ = acos(c); 1 at c ≥ 1, 0 at c ≤ 0.
void gaussian_d_block(double norm, double m, const double* c, double* out);
// GTR (ndf/gtr.h): norm / s^γ, s = α² c² + (1 − c)(1 + c); 0 at c ≤ 0.
void gtr_d_block(double norm, double alpha, double gamma, const double* c, double* out);
// GTR's P22 at kP22Block slopes x: D(c) c⁴ with c² = 1/(1 + x), as Gtr::P22 (s^γ by exp and log).
void gtr_p22_block(double norm, double alpha, double gamma, const double* x, double* out);
// The Gaussian's P22 at kP22Block slopes x: D(c) c⁴ with c² = 1/(1 + x), as Gaussian::P22.
void gaussian_p22_block(double norm, double m, const double* x, double* out);
// SGD's P22 at kP22Block slopes x: K e^{−t − p ln t}/π, t = α + x/α, as Sgd::P22.
void sgd_p22_block(double K, double alpha, double p, const double* x, double* out);
// SGD (ndf/sgd.h): K e^{−t − p ln t}/π/c⁴, t = α + tan²θ/α; 0 at c ≤ 0.
void sgd_d_block(double K, double alpha, double p, const double* c, double* out);
// Blinn-Phong (ndf/blinn_phong.h): (N + 2)/(2π) c^N; 0 at c ≤ 0.
void blinn_phong_d_block(double N, const double* c, double* out);
// Beckmann (ndf/beckmann.h): exp(−tan²θ/α²)/(π α²)/c⁴; 0 at c ≤ 0.
void beckmann_d_block(double alpha, const double* c, double* out);
// Exponential (ndf/exponential.h): exp(−tanθ/α)/(2π α²)/c⁴; 0 at c ≤ 0.
void exponential_d_block(double alpha, const double* c, double* out);
// Exponential power (ndf/exponential_power.h): norm · exp(−(tan²θ/σ²)^p)/c⁴; 0 at c ≤ 0.
void exponential_power_d_block(double norm, double sigma, double p, const double* c, double* out);
// The exponential power's P22 at kP22Block slopes x: norm · exp(−(x/σ²)^p), as
// ExponentialPower::P22 (norm at x ≤ 0).
void exponential_power_p22_block(double norm, double sigma, double p, const double* x, double* out);

}  // namespace brdfkit
