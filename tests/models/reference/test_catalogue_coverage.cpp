// Every model `brdfkit models` lists has a reference test in this folder: a model added to the
// catalogue fails here until its formula is transcribed next to the others.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "brdfkit/models/model.h"

namespace brdfkit {
namespace {

// Model name → the test of this folder that compares it with an independent reference.
const std::set<std::string>& covered() {
  static const std::set<std::string> names = {
      "lambert", "pbrt-diffuse",                                                  // test_lambert_reference.cpp
      "ward", "ward-aniso", "ward-duer",                                          // test_ward_reference.cpp
      "blinn-phong", "lafortune", "lafortune-2", "ashikhmin-shirley",             // test_phong_family_reference.cpp
      "ashikhmin-shirley-dielectric", "ashikhmin-shirley-ngan2005",
      "cook-torrance", "cook-torrance-beckmann", "cook-torrance-blinn-phong",    // test_cook_torrance_reference.cpp
      "cook-torrance-gaussian", "cook-torrance-ggx", "cook-torrance-gtr", "cook-torrance-exponential",
      "cook-torrance-sgd", "cook-torrance-exponential-power", "cook-torrance-beckmann-aniso",
      "cook-torrance-ggx-aniso", "cook-torrance-schlick-rational",
      "cook-torrance-sawicki-rational", "cook-torrance-low2012", "cook-torrance-sgd-bagher2012",
      "poulin-fournier",                                                          // test_poulin_fournier_reference.cpp
      "he",                                                                       // test_he_reference.cpp
      "low-smooth", "low-smooth-2", "low-microfacet", "holzschuch-pacanowski",   // test_low_hp_reference.cpp
      "gltf-metallic-roughness", "mitsuba-roughconductor-beckmann",              // test_renderer_models_reference.cpp
      "mitsuba-roughconductor-ggx", "mitsuba-principled", "pbrt-conductor", "pbrt-conductor-reflectance",
      "pbrt-mix-diffuse-conductor", "disney-principled",
  };
  return names;
}

TEST(ReferenceCoverage, EveryCatalogueModelHasAReference) {
  size_t n = 0;
  for (const Model* m : all_models()) {
    EXPECT_TRUE(covered().count(std::string(m->name()))) << "no reference test for model '" << m->name() << "'";
    ++n;
  }
  EXPECT_EQ(n, covered().size()) << "a covered name is no longer in the catalogue";
}

}  // namespace
}  // namespace brdfkit
