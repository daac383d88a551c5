#pragma once
// For the translation units that hold vector kernels, and only for them (ndf/d_block.cpp,
// shadowing/exponential_power_g1_block.cpp, shadowing/smith_g1_row_block.cpp,
// shadowing/smith_integrand_block.cpp, measured/merl_row_cells.cpp, models/he_series_block.cpp,
// models/he_series_ratios.cpp, models/he_batch_block.cpp, fit/engine/weighted_dots.cpp): never
// include this from a header.
//
// glibc's libmvec holds vector variants of acos, atan, atan2, erfc, exp, log, log1p and pow
// (_ZGVbN2v_exp for SSE2, _ZGVdN4v_exp for AVX2, _ZGVeN8v_exp for AVX-512, within 4 ulp of the
// scalar functions). math.h declares them only under -ffast-math, which would change every other
// expression too. Declaring them here lets GCC vectorize the loops of the files that include this,
// and no other call of libm in the program.
// Each kernel runs a fixed number of values (its callers pad the block), so no value goes
// through a scalar remainder loop: a value depends on its inputs only, not on its position.

extern "C" {
__attribute__((simd("notinbranch"))) double acos(double) noexcept;
__attribute__((simd("notinbranch"))) double atan(double) noexcept;
__attribute__((simd("notinbranch"))) double atan2(double, double) noexcept;
__attribute__((simd("notinbranch"))) double erfc(double) noexcept;
__attribute__((simd("notinbranch"))) double exp(double) noexcept;
__attribute__((simd("notinbranch"))) double log(double) noexcept;
__attribute__((simd("notinbranch"))) double log1p(double) noexcept;
__attribute__((simd("notinbranch"))) double pow(double, double) noexcept;
}

// AVX-512 and AVX2 clones for the CPUs that have them (the build targets baseline x86-64), chosen
// at load time. The AVX-512 clone (eight lanes, libmvec's _ZGVeN8v_ variants) takes a quarter off
// each iteration of a He fit against the AVX2 one. The build's -ffp-contract=off (CMakeLists.txt)
// keeps any clone from fusing a multiply and an add: outside libm calls every clone computes the
// scalar expression to the bit, which the kernels' tests check on whichever clone runs.
#define BRDFKIT_VECTOR_KERNEL [[gnu::target_clones("avx512f", "avx2", "default")]]
