#pragma once
// Parameters the papers published for the 100 MERL materials (data/published-fits/*.json,
// DESIGN.md §10), loaded into brdfkit models with the meaning each file's `conventions` gives
// them (which differs from the papers' printed equations in places):
//
//   file lobe            brdfkit model                   conversion
//   LowSmooth            low-smooth                      A, B, C, eta as published
//   LowAshikhminShirley  ashikhmin-shirley-dielectric    ks = albedo, N = sharpness, eta = fresnelReflectance
//   LowCookTorrance      cook-torrance-low2012           ks = 4·albedo: the file's D has no 1/π and the lobe
//                                                        a 1/π, so albedo·πD·G·F/(π ci co) = 4 albedo · D F G/(4 ci co)
//   Bagher               cook-torrance-sgd-bagher2012    ks = 4·albedo/π (seed 000 Eq. 1 vs seed 004 Eq. 1), alpha, p
//                                                        per channel, F0/F1 = eta[0]/eta[1]; Smith G from the SGD Λ
//                                                        in place of the file's fitted Eq. 9 approximation
//   LowMicrofacetFit     low-microfacet                  A = A[c]/π (the file's lobe carries a 1/π that seed 003
//                                                        Eq. 15 does not print), B, C, eta as published
//   Ngan* (BBM .fit text,     ward, ward-duer, lafortune,      as models/bbm_fit_text.cpp's conventions: ks = albedo,
//   read directly)           cook-torrance, blinn-phong,      4·albedo/π (Cook-Torrance), 4·albedo (Blinn-Phong);
//                            ashikhmin-shirley-ngan2005, he   every colour × MERL's channel factors 1, 1.15, 1.66
// plus the Lambertian albedo → kd everywhere. Values are loaded as published, even where a
// fitting bound of the model is narrower (one Cook-Torrance roughness is 2.09 > 2), unless the
// model is undefined there (not finite, or throwing, at a few direction pairs): such a value is
// refused naming the file, material, parameter and channel.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdfkit/models/model.h"

namespace brdfkit {

class PublishedFits {
 public:
  // Parses one file; throws InputError naming the file (unreadable, not JSON, no `materials`).
  static PublishedFits read(const std::filesystem::path& file);
  // From a document already read (models/bbm_fit_text.h); `file` names it in messages.
  static PublishedFits from_document(nlohmann::json doc, const std::filesystem::path& file);

  const std::filesystem::path& file() const { return file_; }
  std::string stem() const { return file_.stem().string(); }
  // Material names, sorted.
  std::vector<std::string> materials() const;
  // The brdfkit model this file's lobes map to, or empty when unsupported.
  std::string model_name() const { return model_; }
  bool supported() const { return !model_.empty(); }
  // Why the file cannot be loaded into a model (empty when supported).
  const std::string& unsupported_reason() const { return reason_; }
  // The fit of `material`; throws InputError for an unknown material, a missing or malformed
  // field (named in the message), or an unsupported file.
  Brdf brdf(const std::string& material) const;

 private:
  std::filesystem::path file_;
  nlohmann::json materials_;
  std::string lobe_;    // the specular lobe's name in the file
  std::string model_;   // brdfkit model name, empty if unsupported
  std::string reason_;
  std::array<double, 3> channel_scale_{1.0, 1.0, 1.0};  // conventions.channel_scale: every colour × it
};

// The published-fit files of a folder (*.json, and BBM *.fit text), sorted by name.
std::vector<std::filesystem::path> published_fit_files(const std::filesystem::path& dir);

// Löw 2012's Cook-Torrance as their published fits define it: Beckmann D, Cook-Torrance
// dielectric F(η), V-groove G (DESIGN.md §4–6); registered as `cook-torrance-low2012`.
const Model* low_cook_torrance_model();
// Bagher 2012's model as their published fits define it: SGD D, Bagher F0/F1 Fresnel (seed 000
// Eq. 11), uncorrelated Smith G; registered as `cook-torrance-sgd-bagher2012`.
const Model* bagher_sgd_model();

}  // namespace brdfkit
