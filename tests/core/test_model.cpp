#include <gtest/gtest.h>

#include "core/model.hpp"

using namespace dartcheck;

// 002 Def. 10: n-G-map = ([0,n], [0,n], [0,n]+2); n-O-map = ([1,n], [2,n], [1,n]+2).
TEST(Model, GMapPresetFollowsDefinition10) {
  Model m = Model::gmap(3);
  EXPECT_EQ(m.dims, (std::vector<Dim>{0, 1, 2, 3}));
  for (Dim i = 0; i <= 3; ++i) EXPECT_FALSE(m.is_oriented(i));
  EXPECT_EQ(m.exchangeable, (std::vector<std::pair<Dim, Dim>>{{0, 2}, {0, 3}, {1, 3}}));
}

TEST(Model, OMapPresetFollowsDefinition10) {
  Model m = Model::omap(3);
  EXPECT_EQ(m.dims, (std::vector<Dim>{1, 2, 3}));
  EXPECT_TRUE(m.is_oriented(1));
  EXPECT_FALSE(m.is_oriented(2));
  EXPECT_FALSE(m.is_oriented(3));
  EXPECT_EQ(m.exchangeable, (std::vector<std::pair<Dim, Dim>>{{1, 3}}));
  EXPECT_TRUE(Model::omap(2).exchangeable.empty());
}

TEST(Model, VariantsOfSection3_2) {
  EXPECT_TRUE(Model::closed_gmap(2).loop_free);
  Model open = Model::open_omap(2);
  EXPECT_TRUE(has_dim(open.partial, 2));
  EXPECT_FALSE(has_dim(open.partial, 1));
}

TEST(Model, ParsesNamesAndRejectsOthers) {
  EXPECT_EQ(Model::by_name("2-gmap"), Model::gmap(2));
  EXPECT_EQ(Model::by_name("3-omap"), Model::omap(3));
  EXPECT_EQ(Model::by_name("2-closed-gmap"), Model::closed_gmap(2));
  EXPECT_EQ(Model::by_name("3-open-omap"), Model::open_omap(3));
  for (auto bad : {"", "gmap", "2gmap", "0-omap", "16-gmap", "-1-gmap", "2-gmaps", "2-cmap"}) EXPECT_FALSE(Model::by_name(bad)) << bad;
}
