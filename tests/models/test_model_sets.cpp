// The model sets `fit-all --models` takes: lobes counted from each model's parameter table.
#include <gtest/gtest.h>

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
  EXPECT_EQ(single.size(), 23u);  // the README's count of single-lobe models
  for (const Model* m : single) EXPECT_EQ(lobe_count(*m), 1) << m->name();
  const auto renderer = parse_model_set("renderer");
  EXPECT_EQ(renderer.size(), 9u);
  for (const Model* m : renderer) EXPECT_TRUE(is_renderer_model(*m)) << m->name();
  const auto list = parse_model_set("ward,lambert,ward");
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0]->name(), "ward");
  EXPECT_THROW(parse_model_set("ward,nope"), InputError);
  EXPECT_THROW(parse_model_set(","), InputError);
}

}  // namespace
}  // namespace brdfkit
