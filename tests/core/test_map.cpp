#include <gtest/gtest.h>

#include "core/map.hpp"
#include "core/orbit.hpp"

using namespace dartcheck;

TEST(Map, OrientedDimensionKeepsPredecessor) {
  Map m(Model::omap(2), 3);
  m.sew(1, 0, 1);
  m.sew(1, 1, 2);
  m.sew(1, 2, 0);
  EXPECT_EQ(m.link(1, 0), 1u);
  EXPECT_EQ(m.inverse_link(1, 1), 0u);
  EXPECT_EQ(m.inverse_link(1, 0), 2u);
  m.set_link(1, 0, 2);  // 1 loses its predecessor, 2 gains 0
  EXPECT_EQ(m.inverse_link(1, 1), no_dart);
  EXPECT_EQ(m.inverse_link(1, 2), 0u);
}

TEST(Map, NonOrientedSewIsSymmetric) {
  Map m(Model::gmap(1), 2);
  m.sew(0, 0, 1);
  EXPECT_EQ(m.link(0, 1), 0u);
  EXPECT_EQ(m.inverse_link(0, 0), 1u);
  m.sew(1, 0, 0);
  EXPECT_EQ(m.link(1, 0), 0u);
}

TEST(Map, RelocateRedirectsEveryArc) {
  // A 1-cycle 0 -> 1 -> 2 -> 0 with 2-links 0-2, 1-1 in a 2-O-map; move 2 into a fresh slot 3.
  Map m(Model::omap(2), 4);
  m.sew(1, 0, 1);
  m.sew(1, 1, 2);
  m.sew(1, 2, 0);
  m.sew(2, 0, 2);
  m.sew(2, 1, 1);
  m.relocate(2, 3);
  EXPECT_EQ(m.link(1, 1), 3u);
  EXPECT_EQ(m.link(1, 3), 0u);
  EXPECT_EQ(m.inverse_link(1, 0), 3u);
  EXPECT_EQ(m.inverse_link(1, 3), 1u);
  EXPECT_EQ(m.link(2, 0), 3u);
  EXPECT_EQ(m.link(2, 3), 0u);
  EXPECT_EQ(m.link(1, 2), no_dart);
  m.truncate(3);
  EXPECT_EQ(m.size(), 3u);
}

TEST(Map, RelocateKeepsLoops) {
  Map m(Model::gmap(2), 2);
  m.sew(0, 0, 0);
  m.relocate(0, 1);
  EXPECT_EQ(m.link(0, 1), 1u);
}

TEST(Orbit, WalkerClearsItsMarksBetweenCalls) {
  // Two disjoint 0-edges: {0,1} and {2,3}.
  Map m(Model::gmap(0), 4);
  m.sew(0, 0, 1);
  m.sew(0, 2, 3);
  OrbitWalker w(m);
  auto gens = dims_generators({0});
  EXPECT_EQ(w.orbit(0, gens).size(), 2u);
  EXPECT_EQ(w.orbit(0, gens).size(), 2u);
  EXPECT_EQ(w.orbit(3, gens).size(), 2u);
  EXPECT_EQ(w.count_orbits(gens), 2u);
  EXPECT_EQ(w.count_orbits(gens), 2u);
}
