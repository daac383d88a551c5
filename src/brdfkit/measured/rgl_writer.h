#pragma once
// Writes any BRDF as an RGL `tensor_file` (the format of measured/rgl_tensor.h, readable
// by Mitsuba 3's `measured` plugin and pbrt-v4's MeasuredBxDF), parameterized as Dupuy & Jakob
// 2018 §5 do for their measurements:
//   1. D(θ, φ) from the retro-reflection ρ(ω, ω) by power iteration (Dupuy et al. 2015: for a
//      microfacet BRDF ρ(ω, ω) ∝ D(ω) G1(ω)² / cos²θ with G1 = cosθ / σ(ω), so D ∝ ρ(ω, ω) σ(ω)²,
//      σ recomputed from D each round), normalized to ∫ D cosθ dω = 1;
//   2. σ(ω) = ∫ D(m) max(0, ω·m) dωm, the projected area, by quadrature of that table;
//   3. per incidence node (φi, θi) the VNDF D(m) max(0, ωi·m) on the unit square of the half
//      vector (with the square's Jacobian), the warp that spreads the colour grid over the lobe;
//   4. the colour grid: at node (x, y) the half vector the VNDF warp sends it to, wo = ωi mirrored
//      there, and the value ρ(ωi, wo) · 4 σ(ωi) cosθo / D(m) (with `jacobian` = 1 the reader
//      multiplies by D / (4 σ cosθo) again, DESIGN.md §2), and its luminance;
//   5. the same grid as `spectra` over 380–780 nm, the smoothest spectrum of each colour under
//      brdfkit's spectrum → RGB convention (measured/spectral_rgb.h), for Mitsuba 3's `measured`,
//      which reads spectra only; brdfkit's reader takes `rgb` when present and gets each colour
//      back from `spectra` alone to rounding.
// The reader's own interpolants give D, σ and the warp here, so every grid node reads back the
// value written for it. An isotropic file has one incidence azimuth and half-vector azimuths
// relative to it; an anisotropic one (phi_i > 1) follows Mitsuba 3's `measured` plugin: absolute
// half-vector azimuths, D and σ tabulated over (θ, φ), and the incidence azimuths of one of
// 1, 2 or 4 copies of the circle (the source's symmetry, see RglWriteOptions::symmetry).
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "brdfkit/core/vec.h"

namespace brdfkit {

struct RglWriteOptions {
  int theta_i = 16;      // incidence nodes, uniform in cosθ from 0° to 90° (the last on the horizon)
  // Incidence azimuth nodes: 1 writes an isotropic file (the source is asked for wi in the x-z
  // plane only); more write an anisotropic file with this many nodes from -π to -π + 2π/symmetry.
  int phi_i = 1;
  // Anisotropic files: the symmetry of the source that the file relies on. 1: none (every
  // azimuth stored); 2: ρ unchanged by a half turn of both directions about the normal (every
  // microfacet model whose D(m) = D(-m) in the tangent plane), φi ∈ [-π, 0] stored; 4: also
  // unchanged by mirrors about the x and y axes, φi ∈ [-π, -π/2] stored.
  int symmetry = 1;
  // Colour grid per incidence node (grid × grid). 32, as Dupuy & Jakob's files, keeps the albedo of
  // a GGX α = 0.25 lobe on a diffuse base within 0.9 % up to θi = 80°, 64 within 0.08 %
  // (tests/measured/test_rgl_writer.cpp).
  int grid = 64;
  int ndf_nodes = 128;   // θ nodes of the NDF and σ tables, uniform in u = sqrt(2θ/π)
  int ndf_azimuths = 64; // φ nodes of an anisotropic file's NDF and σ tables, from -π to π
  int vndf_nodes = 128;  // VNDF table per incidence node (nodes × nodes)
  int power_iterations = 4;
  bool rgb_table = true;  // also write `rgb` (spectra are always written)
  std::string description;
};

// ρ(wi, wo) in sr⁻¹ (nullopt: not measured, written as 0 and marked invalid). For an isotropic
// file it is only asked for wi in the x-z plane.
using RglSource = std::function<std::optional<Rgb>(const Vec3d& wi, const Vec3d& wo)>;

// Builds the tables and writes them atomically (write to a temporary, rename). InputError for
// options out of range, for a source whose retro-reflection is nowhere positive, and for
// non-finite values (naming the direction pair).
void write_rgl(const std::filesystem::path& file, const RglSource& rho, const RglWriteOptions& options = {});

}  // namespace brdfkit
