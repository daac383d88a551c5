#include <gtest/gtest.h>
#include "brdfkit/models/model.h"
TEST(CatalogueSmoke, Lists) { EXPECT_NO_THROW(brdfkit::model_by_name("ward")); }
