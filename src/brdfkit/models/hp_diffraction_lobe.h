#pragma once
// Holzschuch & Pacanowski 2015's diffraction lobe (seed 004 §5.1, Eq. 10, 16–17, 25; DESIGN.md §6)
// for one wavelength λ (µm), without its colour kw/λ⁴ and without the shadowing G the full
// model (models/holzschuch_pacanowski.h) applies to it:
//   Sz(f) = (1 + f²/a²)^{−2},   f = ‖(wi + wo) × n‖/λ  (Eq. 10; = (2/λ) sinθh cosθd, Eq. 11),
//   lobe = Sz(f) / E_{a,λ}.
// E_{a,λ} is the lobe's largest albedo ∫ Sz cosθo dωo, reached at normal incidence, where
// f = sinθo/λ: with k = aλ and s = sinθo,
//   E = 2π ∫₀¹ s/(1 + s²/k²)² ds = π k²/(1 + k²) = π/(1 + 1/(a²λ²)).
// Seed 004 §5.1 prints E = π(1 + 1/(a²λ²)), too large by (1 + 1/(a²λ²))²: at a = 0.91 µm⁻¹,
// λ = 0.645 µm (nickel's fitted a, red) the lobe divided by the printed E reflects 0.066 at
// normal incidence instead of 1 (quadrature in tests/catalogue_low_hp/test_hp_diffraction.cpp).
// brdfkit divides by the correct value, so kw/λ⁴ is the lobe's albedo at normal incidence
// when G = 1.
#include <cmath>

#include "brdfkit/core/vec.h"

namespace brdfkit {

template <class T> struct HpDiffractionLobe {
  T a;            // spatial-frequency parameter, µm⁻¹ (seed 004 Eq. 16)
  double lambda;  // wavelength, µm

  // π k²/(1 + k²), k = aλ (see the header comment).
  T energy() const {
    const T k2 = a * a * T(lambda * lambda);
    return T(kPi) * k2 / (T(1) + k2);
  }
  // The value seed 004 §5.1 prints, kept for the test that shows it does not normalize.
  T printed_energy() const { return T(kPi) * (T(1) + T(1) / (a * a * T(lambda * lambda))); }

  // Sz(f) with f² = ‖(wi + wo)_xy‖²/λ² (Eq. 10, 25): f²/a² = ‖(wi + wo)_xy‖²/(aλ)².
  T sz(const Vec3<T>& wi, const Vec3<T>& wo) const {
    const T sx = wi.x() + wo.x(), sy = wi.y() + wo.y();
    const T k2 = a * a * T(lambda * lambda);
    const T q = T(1) + (sx * sx + sy * sy) / k2;
    return T(1) / (q * q);
  }
  // Sz / E_{a,λ} (Eq. 17 without kw/λ⁴).
  T eval(const Vec3<T>& wi, const Vec3<T>& wo) const { return sz(wi, wo) / energy(); }
};

}  // namespace brdfkit
