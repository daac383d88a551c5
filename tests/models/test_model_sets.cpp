// The model sets `fit-all --models` takes: lobes counted from each model's parameter table.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "brdfkit/core/error.h"
#include "brdfkit/models/model_sets.h"

namespace brdfkit {
namespace {

TEST(ModelSets, LobeCountsAndSetsComeFromTheParameterTables) {
  EXPECT_EQ(lobe_count(model_by_name("lambert")), 0);
  for (const char* m : {"cook-torrance-ggx", "ward", "blinn-phong", "ashikhmin-shirley", "low-smooth", "lafortune"})
    EXPECT_EQ(lobe_count(model_by_name(m)), 1) << m;
  for (const char* m : {"lafortune-2", "low-smooth-2"}) EXPECT_EQ(lobe_count(model_by_name(m)), 2) << m;
  const auto single = parse_model_set("single-lobe");
  const auto all = parse_model_set("all");
  EXPECT_EQ(all.size(), all_models().size());
  // The README's main job: 24 single-lobe models, He and the 23 others, in catalogue order.
  // Excluded: lambert (no lobe), lafortune-2 and low-smooth-2 (two), holzschuch-pacanowski (ks and
  // kw), and the renderers' BSDFs (gltf-, mitsuba-, pbrt-, disney-: their own set, "renderer").
  const std::vector<std::string> want = {
      "cook-torrance", "cook-torrance-beckmann", "cook-torrance-blinn-phong", "cook-torrance-gaussian",
      "cook-torrance-ggx", "cook-torrance-gtr", "cook-torrance-exponential", "cook-torrance-sgd",
      "cook-torrance-exponential-power", "cook-torrance-schlick-rational", "cook-torrance-sawicki-rational",
      "ward", "ward-aniso", "ward-duer", "blinn-phong", "lafortune", "ashikhmin-shirley",
      "ashikhmin-shirley-dielectric", "ashikhmin-shirley-ngan2005", "he", "low-smooth", "low-microfacet", "cook-torrance-low2012",
      "cook-torrance-sgd-bagher2012"};
  ASSERT_EQ(want.size(), 24u);
  std::vector<std::string> got;
  for (const Model* m : single) got.emplace_back(m->name());
  EXPECT_EQ(got, want);
  for (const Model* m : single) EXPECT_EQ(lobe_count(*m), 1) << m->name();
  for (const char* m : {"lambert", "lafortune-2", "low-smooth-2", "holzschuch-pacanowski"})
    EXPECT_NE(lobe_count(model_by_name(m)), 1) << m;
  const auto renderer = parse_model_set("renderer");
  EXPECT_EQ(renderer.size(), 9u);
  for (const Model* m : renderer) EXPECT_TRUE(is_renderer_model(*m)) << m->name();
  // Lobes turned by a fitted tangent angle: their own set, not in single-lobe.
  std::vector<std::string> aniso;
  for (const Model* m : parse_model_set("anisotropic")) aniso.emplace_back(m->name());
  EXPECT_EQ(aniso, (std::vector<std::string>{"cook-torrance-beckmann-aniso", "cook-torrance-ggx-aniso", "poulin-fournier",
                                             "ward-aniso"}));
  const auto list = parse_model_set("ward,lambert,ward");
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0]->name(), "ward");
  EXPECT_THROW(parse_model_set("ward,nope"), InputError);
  EXPECT_THROW(parse_model_set(","), InputError);
}

}  // namespace
}  // namespace brdfkit
