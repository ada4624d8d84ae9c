#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/map.hpp"
#include "core/orbit.hpp"
#include "generators/random_maps.hpp"

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

// partition_orbits against the walker, on random maps of every model the
// generator builds and every cell dimension: the orbits counted alike
// (count_orbits walks its own way), first[k] the smallest dart of orbit k,
// and two darts in one orbit exactly when the walker's orbit of the first
// holds the second.
TEST(Orbit, PartitionAgreesWithTheWalker) {
  std::mt19937 rng(36);
  for (const Model& model : {Model::gmap(2), Model::gmap(3), Model::omap(2), Model::omap(3)})
    for (int k = 0; k < 20; ++k) {
      const Map m = build_random_map(model, draw_recipe(rng, 1 + k % 7, model.dimension()));
      OrbitWalker walker(m);
      for (int cell = 0; cell <= model.dimension(); ++cell) {
        const auto gens = cell_generators(model, cell);
        const OrbitPartition p = partition_orbits(m, gens);
        ASSERT_EQ(p.size(), walker.count_orbits(gens));
        for (std::size_t o = 0; o < p.size(); ++o) {
          const auto& darts = walker.orbit(p.first[o], gens);
          EXPECT_EQ(*std::min_element(darts.begin(), darts.end()), p.first[o]);
          for (Dart e : darts) EXPECT_EQ(p.of[e], o);
        }
      }
    }
}
