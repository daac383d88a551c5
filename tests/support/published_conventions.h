#pragma once
// The published Löw 2012 fits (data/published-fits/low2012-*.json) evaluated from their own JSON,
// with the formulas each file's `conventions` block states, written out here independently of
// brdfkit's models (models/published_fits.cpp maps them onto those). ρ = albedo/π of the
// "Lambertian" lobe plus one of:
//   LowSmooth:           A (1 + B |Dp|²)^−C F(sqrt(1 − |Lp − Vp|²/4); eta)
//   LowAshikhminShirley: albedo (n+1)/(8π) cosⁿθh F(wi·h; fresnelReflectance) / ((wi·h) max(ci, co))
//   LowCookTorrance:     albedo exp(−tan²θh/m²)/(m² cos⁴θh) G F(wi·h; eta) / (π ci co), m = roughness
//   LowMicrofacetFit:    A (1 + B (1 − cosθh))^−C G F(wi·h; eta) / (π ci co)
// with G the Cook-Torrance V-groove term and F the unpolarized dielectric Fresnel of Cook &
// Torrance 1982, as the files print them. Bagher 2012 (bagher2012-sgd.json) is not here: brdfkit's
// Smith G differs from the file's fitted Eq. 9 by design (test_published_fits.cpp compares it near
// normal incidence).
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "brdfkit/core/vec.h"

namespace brdfkit::test {

// Cook-Torrance unpolarized dielectric Fresnel at c = cosθ, as the files' conventions print it.
inline double conventions_fresnel(double c, double eta) {
  const double g = std::sqrt(eta * eta + c * c - 1);
  const double a = (g - c) / (g + c), b = (c * (g + c) - 1) / (c * (g - c) + 1);
  return 0.5 * a * a * (1 + b * b);
}

// ρ of one material's lobes (the JSON array under materials[name]) at (wi, wo), per channel;
// nullopt when its specular lobe is not one of the four above.
inline std::optional<Rgb> low2012_conventions_rho(const nlohmann::json& lobes, const Vec3d& wi, const Vec3d& wo) {
  const nlohmann::json* kd = nullptr;
  const nlohmann::json* spec = nullptr;
  std::string kind;
  for (const auto& l : lobes) {
    if (l["lobe"] == "Lambertian") kd = &l["params"]["albedo"];
    else spec = &l["params"], kind = l["lobe"].get<std::string>();
  }
  if (!kd || !spec) return std::nullopt;
  const auto& p = *spec;
  const Vec3d h = (wi + wo).normalized();
  const double ci = wi.z(), co = wo.z(), ch = h.z(), cd = wi.dot(h);
  const double g = std::min({1.0, 2 * ch * co / wo.dot(h), 2 * ch * ci / wo.dot(h)});
  Rgb rho;
  for (int c = 0; c < 3; ++c) {
    double s;
    if (kind == "LowSmooth") {
      const double dp2 = std::pow(wi.x() + wo.x(), 2) + std::pow(wi.y() + wo.y(), 2);
      const double lv2 = std::pow(wi.x() - wo.x(), 2) + std::pow(wi.y() - wo.y(), 2);
      s = p["A"][c].get<double>() * std::pow(1 + p["B"].get<double>() * dp2, -p["C"].get<double>()) *
          conventions_fresnel(std::sqrt(1 - lv2 / 4), p["eta"].get<double>());
    } else if (kind == "LowAshikhminShirley") {
      const double n = p["sharpness"].get<double>();
      s = p["albedo"][c].get<double>() * (n + 1) / (8 * kPi) * std::pow(ch, n) *
          conventions_fresnel(cd, p["fresnelReflectance"].get<double>()) / (cd * std::max(ci, co));
    } else if (kind == "LowCookTorrance") {
      const double m = p["roughness"].get<double>(), tan2 = (1 - ch * ch) / (ch * ch);
      const double d = std::exp(-tan2 / (m * m)) / (m * m * std::pow(ch, 4));
      s = p["albedo"][c].get<double>() * d * g * conventions_fresnel(cd, p["eta"].get<double>()) / (kPi * ci * co);
    } else if (kind == "LowMicrofacetFit") {
      s = p["A"][c].get<double>() * std::pow(1 + p["B"].get<double>() * (1 - ch), -p["C"].get<double>()) * g *
          conventions_fresnel(cd, p["eta"].get<double>()) / (kPi * ci * co);
    } else {
      return std::nullopt;
    }
    rho[c] = (*kd)[c].get<double>() / kPi + s;
  }
  return rho;
}

}  // namespace brdfkit::test
