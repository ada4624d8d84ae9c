// Tetrahedral maps, the modify operations, the hex queries and the
// recombination (001 Sec. 6-7.1). Expectations: counts derived by hand
// (darts per tetrahedron and face, volumes), check_map on every result,
// the chirality count of test_hex_subdivisions (336 oriented patterns),
// and hex grids cut by known patterns, whose every hex must be found.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <random>
#include <set>

#include "checkers/map_validity.hpp"
#include "core/input_error.hpp"
#include "core/orbit.hpp"
#include "grid_tets.hpp"
#include "io/tet_mesh_io.hpp"
#include "querymodify/map_checks.hpp"
#include "querymodify/modify.hpp"
#include "querymodify/overlap.hpp"
#include "querymodify/recombination.hpp"

namespace dartcheck::querymodify::test {
namespace {

// Kuhn's 6 tetrahedra around the diagonal 0-7 (0 -> e_a -> e_a + e_b ->
// 7 for each order of the axes): every face split by the diagonal through
// its lowest corner, so all hexes of a grid agree. Built directly, without
// the enumeration.
std::uint64_t kuhn() {
  std::uint64_t s = 0;
  std::array<int, 3> axes{0, 1, 2};
  do {
    const unsigned a = 1u << axes[0], ab = a | (1u << axes[1]);
    const unsigned mask = (1u << 0) | (1u << a) | (1u << ab) | (1u << 7);
    const auto& c = candidate_tets();
    s |= std::uint64_t{1} << (std::lower_bound(c.begin(), c.end(), static_cast<TetMask>(mask)) - c.begin());
  } while (std::next_permutation(axes.begin(), axes.end()));
  return s;
}

std::size_t volumes(const Map& m) {
  OrbitWalker w(m);
  return w.count_orbits(dims_generators({1, 2}));
}

std::size_t free3(const Map& m) {
  std::size_t n = 0;
  for (Dart d = 0; d < m.size(); ++d) n += m.link(3, d) == no_dart;
  return n;
}

HexGrid kuhn_grid(std::uint32_t n) {
  const std::uint64_t s = kuhn();
  const int d = subdivision_diagonals(s);
  // Kuhn's diagonals: x faces split the same way on both sides, and so on.
  return hex_grid(
      n, [&](auto, auto, auto, int) { return s; }, [&](auto, auto, auto, int axis) { return ((d >> (2 * axis)) & 1) != 0; });
}

// A grid where every face gets a random diagonal and every hex a random
// labeled subdivision with those diagonals, so that all classes appear
// (grid_tets.hpp).
HexGrid random_grid(std::uint32_t n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  return random_hexes(n, rng);
}

TEST(TetMap, GridOfKuhnHexes) {
  ASSERT_EQ(subdivision_tets(kuhn()).size(), 6u);
  const HexGrid g = kuhn_grid(2);
  ASSERT_EQ(g.tets.size(), 48u);
  const TetMap t = build_tet_map(g.tets, &g.points);
  EXPECT_TRUE(check_3map(t.map).valid());
  EXPECT_EQ(t.map.size(), 12u * 48);
  EXPECT_EQ(volumes(t.map), 48u);
  // Boundary: 6 sides x 4 squares x 2 triangles x 3 darts.
  EXPECT_EQ(free3(t.map), 6u * 4 * 2 * 3);
  // Without points, orientations propagate across faces: the same counts.
  const TetMap c = build_tet_map(g.tets);
  EXPECT_TRUE(check_3map(c.map).valid());
  EXPECT_EQ(free3(c.map), free3(t.map));
}

TEST(TetMap, EverySubdivisionIsAValidBall) {
  // Every labeled subdivision builds a valid map whose free darts are the
  // 12 boundary triangles of the hex: 36.
  for (auto s : enumerate_hex_subdivisions()) {
    const TetMap t = build_tet_map(subdivision_tets(s));
    ASSERT_TRUE(check_3map(t.map).valid());
    ASSERT_EQ(free3(t.map), 36u);
  }
}

// Meshes that make no 3-map name the tetrahedron that shows it.
TEST(TetMap, BadMeshesNameATetrahedron) {
  const std::vector<std::array<double, 3>> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {1, 1, 1}, {0.2, 0.2, 0.2}};
  auto tet_of_error = [](auto&& build) -> long {
    try {
      build();
    } catch (const BuildError& e) {
      EXPECT_EQ(e.culprit(), BuildError::Culprit::cell);
      return static_cast<long>(e.index());
    }
    return -1;
  };
  // Face 0 1 2 in three tetrahedra: the third is named.
  EXPECT_EQ(tet_of_error([&] { build_tet_map({{0, 1, 2, 3}, {0, 1, 2, 4}, {0, 1, 2, 5}}, &p); }), 2);
  // Vertex 6 inside tetrahedron 0: 0 1 2 6 lies on the same side of 0 1 2.
  EXPECT_EQ(tet_of_error([&] { build_tet_map({{0, 1, 2, 3}, {0, 1, 2, 6}}, &p); }), 1);
  // Flat: four points in one plane.
  const std::vector<std::array<double, 3>> flat{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  EXPECT_EQ(tet_of_error([&] { build_tet_map({{0, 1, 2, 3}}, &flat); }), 0);
  // Without points the same pair orients fine (it is a valid complex).
  EXPECT_TRUE(check_3map(build_tet_map({{0, 1, 2, 3}, {0, 1, 2, 6}}).map).valid());
}

// The corrected delete: removing the centre tetrahedra of a Kuhn hex frees
// the faces its neighbours shared with it.
TEST(Modify, DeleteFreesTheNeighbours) {
  const HexGrid g = kuhn_grid(2);
  TetMap t = build_tet_map(g.tets, &g.points);
  std::vector<Dart> darts;
  for (Dart d = 0; d < 12; ++d) darts.push_back(d);  // tetrahedron 0
  std::size_t shared = 0;
  for (Dart d : darts) shared += t.map.link(3, d) != no_dart;
  const std::size_t before = free3(t.map);
  delete_volumes(t.map, darts);
  EXPECT_TRUE(check_3map(t.map).valid());
  EXPECT_EQ(t.map.size(), 12u * 47);
  // Its free darts go, its neighbours' darts on the shared faces become free.
  EXPECT_EQ(free3(t.map), before - (12 - shared) + shared);
}

// 001's Alg. 3 as written: only 3-links between two darts of the query are
// unsewn, so a neighbour outside the query keeps a link to a deleted dart.
TEST(Modify, PaperDeleteLeavesADanglingLink) {
  const HexGrid g = kuhn_grid(1);
  TetMap t = build_tet_map(g.tets, &g.points);
  Map m = t.map;
  std::vector<bool> in(m.size(), false);
  for (Dart d = 0; d < 12; ++d) in[d] = true;
  for (Dart d = 0; d < 12; ++d)
    if (const Dart e = m.link(3, d); e != no_dart && in[e]) m.remove_link(3, d);  // unsew inside the query only
  for (Dart d = 0; d < 12; ++d)
    for (Dim i : m.model().dims) m.remove_link(i, d);
  EXPECT_FALSE(check_3map(m).valid());  // the neighbours still point at darts 0..11
}

TEST(Modify, MergeRandomConnectedSets) {
  std::mt19937 rng(5);
  const HexGrid g = random_grid(2, 17);
  for (int run = 0; run < 40; ++run) {
    TetMap t = build_tet_map(g.tets);  // some tetrahedra are flat in the unit grid: orient combinatorially
    // A random set of tetrahedra grown across shared faces.
    std::set<std::uint32_t> chosen{static_cast<std::uint32_t>(rng() % t.tets.size())};
    const std::size_t want = 1 + rng() % 6;
    for (std::size_t guard = 0; chosen.size() < want && guard < 100; ++guard) {
      const auto from = *std::next(chosen.begin(), static_cast<long>(rng() % chosen.size()));
      const Dart e = t.map.link(3, 12 * from + rng() % 12);
      if (e != no_dart) chosen.insert(e / 12);
    }
    // Faces between two chosen tetrahedra (counted from the tetrahedra).
    std::size_t inner = 0;
    for (auto a : chosen)
      for (auto b : chosen)
        if (a < b) {
          std::vector<std::uint32_t> x(g.tets[a].begin(), g.tets[a].end()), y(g.tets[b].begin(), g.tets[b].end()), both;
          std::sort(x.begin(), x.end());
          std::sort(y.begin(), y.end());
          std::set_intersection(x.begin(), x.end(), y.begin(), y.end(), std::back_inserter(both));
          inner += both.size() == 3;
        }
    std::vector<Dart> darts;
    for (auto c : chosen)
      for (Dart d = 0; d < 12; ++d) darts.push_back(12 * c + d);
    const std::size_t vols = volumes(t.map), size = t.map.size();
    merge_volumes(t.map, darts);
    ASSERT_TRUE(check_3map(t.map).valid()) << "run " << run;
    EXPECT_EQ(t.map.size(), size - 6 * inner);
    // The merged tetrahedra are one volume if the set is connected by faces.
    EXPECT_EQ(volumes(t.map), vols - chosen.size() + 1);
  }
}

// An oriented tetrahedral complex as sorted (tetrahedron, sign) pairs:
// the sign says whether the oriented tuple is an even permutation of the
// sorted one.
using OrientedTets = std::vector<std::pair<std::array<std::uint32_t, 4>, int>>;

OrientedTets oriented(const std::vector<std::array<std::uint32_t, 4>>& tets) {
  OrientedTets out;
  for (auto t : tets) {
    int sign = 1;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b + 1 < 4 - a; ++b)
        if (t[static_cast<std::size_t>(b)] > t[static_cast<std::size_t>(b + 1)]) {
          std::swap(t[static_cast<std::size_t>(b)], t[static_cast<std::size_t>(b + 1)]);
          sign = -sign;
        }
    out.push_back({t, sign});
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The smallest image under all 8! vertex permutations (with `signs`
// false, orientation ignored).
OrientedTets canonical_complex(const std::vector<std::array<std::uint32_t, 4>>& tets, bool signs) {
  std::array<std::uint32_t, 8> p{0, 1, 2, 3, 4, 5, 6, 7};
  OrientedTets best;
  do {
    std::vector<std::array<std::uint32_t, 4>> image;
    for (const auto& t : tets) image.push_back({p[t[0]], p[t[1]], p[t[2]], p[t[3]]});
    auto o = oriented(image);
    if (!signs)
      for (auto& x : o) x.second = 0;
    if (best.empty() || o < best) best = o;
  } while (std::next_permutation(p.begin(), p.end()));
  return best;
}

TEST(HexQueries, BothHandsOfEveryClass) {
  const auto queries = hex_queries();
  // The 174 classes and their mirror images are 336 rotation classes of
  // labeled subdivisions (test_hex_subdivisions), but only 322 distinct
  // oriented tetrahedral maps: some subdivisions are isomorphic as
  // complexes by a vertex permutation that is no symmetry of the cube
  // (their boundary triangles pair into quads in more than one way). A
  // query only sees the complex, so 322 queries. Oracle: the oriented
  // complexes up to all 8! vertex permutations.
  std::set<OrientedTets> oriented_classes, complexes;
  std::set<std::uint64_t> classes;
  for (auto s : enumerate_hex_subdivisions()) classes.insert(canonical_subdivision(s));
  for (auto s : classes) {
    auto tets = build_tet_map(subdivision_tets(s)).tets;  // consistently oriented
    oriented_classes.insert(canonical_complex(tets, true));
    for (auto& t : tets) std::swap(t[2], t[3]);
    oriented_classes.insert(canonical_complex(tets, true));
    complexes.insert(canonical_complex(tets, false));
  }
  EXPECT_EQ(queries.size(), oriented_classes.size());
  RecordProperty("oriented_complexes", static_cast<int>(oriented_classes.size()));
  RecordProperty("complexes", static_cast<int>(complexes.size()));
  std::cerr << "oriented complexes " << oriented_classes.size() << ", complexes " << complexes.size() << "\n";
  std::size_t min_tets = 100, max_tets = 0;
  for (const auto& q : queries) {
    min_tets = std::min(min_tets, q.tets);
    max_tets = std::max(max_tets, q.tets);
  }
  EXPECT_EQ(min_tets, 5u);
  EXPECT_EQ(max_tets, 15u);  // "between 5 and 15 tetrahedra" (Pellerin et al.)
}

// Every hex of grids cut by known patterns is among the matches, and a
// selection merges into hexes of 36 darts next to tetrahedra of 12.
// The maps are oriented combinatorially (some subdivisions have flat
// tetrahedra on a unit grid); the points only score the global strategy.
void every_hex_found(const HexGrid& g, const std::vector<HexQuery>& queries) {
  TetMap t = build_tet_map(g.tets);
  QueryTrie trie;
  for (std::size_t k = 0; k < queries.size(); ++k) trie.add(queries[k].word, static_cast<int>(k));
  const auto all = all_matches(t.map, trie);
  std::set<std::vector<Dart>> found;
  for (const auto& m : all.distinct) {
    auto d = m.darts;
    std::sort(d.begin(), d.end());
    found.insert(d);
  }
  for (const auto& tets : g.hex_tets) {
    std::vector<Dart> darts;
    for (auto tt : tets)
      for (Dart d = 0; d < 12; ++d) darts.push_back(12 * tt + d);
    std::sort(darts.begin(), darts.end());
    EXPECT_TRUE(found.count(darts)) << "a hex of " << tets.size() << " tetrahedra was not found";
  }
  // Greedy (the word search), global by the vertex search and by words.
  for (const auto& [s, search] :
       {std::pair{Strategy::greedy, Search::words}, std::pair{Strategy::global, Search::vertices}, std::pair{Strategy::global, Search::words}}) {
    TetMap copy = build_tet_map(g.tets);
    const auto r = recombine(copy, queries, s, &g.points, 0.0, search);
    EXPECT_EQ(r.search, search);
    EXPECT_TRUE(check_3map(copy.map).valid());
    EXPECT_EQ(copy.map.size(), 36 * r.hexes + 12 * r.tets);
    EXPECT_EQ(volumes(copy.map), r.hexes + r.tets);
    if (s == Strategy::global) {
      // On a grid of unit cubes the best score is the real hexes' (1.0,
      // with the query's best reading as a hexahedron): the global
      // strategy recovers every one of them.
      EXPECT_EQ(r.hexes, g.hex_tets.size());
      EXPECT_EQ(r.tets, 0u);
      // Each hex is read as its grid cube: corner v = x + 2y + 4z sits at
      // the cube's minimum plus (x, y, z) (or a mirror of it), quality 1.
      std::set<std::set<std::uint32_t>> cubes;
      for (const auto& tets : g.hex_tets) {
        std::set<std::uint32_t> v;
        for (auto tt : tets) v.insert(g.tets[tt].begin(), g.tets[tt].end());
        cubes.insert(v);
      }
      for (std::size_t h = 0; h < r.hexes; ++h) {
        const auto& c = r.hex_corners[h];
        EXPECT_TRUE(cubes.count(std::set<std::uint32_t>(c.begin(), c.end())));
        EXPECT_NEAR(r.quality[h], 1.0, 1e-12);
        for (int v = 0; v < 8; ++v)
          for (int axis = 0; axis < 3; ++axis) {
            const auto& a = g.points[c[static_cast<std::size_t>(v)]];
            const auto& b = g.points[c[static_cast<std::size_t>(v ^ (1 << axis))]];
            double length = 0;
            for (int k = 0; k < 3; ++k) length += (a[k] - b[k]) * (a[k] - b[k]);
            EXPECT_NEAR(length, 1.0, 1e-12) << "corners " << v << " and " << (v ^ (1 << axis)) << " are not a cube edge";
          }
      }
    } else {
      EXPECT_EQ(r.hex_corners.size(), r.hexes);
      EXPECT_EQ(r.remaining_tets.size(), r.tets);
    }
  }
}

TEST(Recombination, KuhnGridEveryHexFound) { every_hex_found(kuhn_grid(3), hex_queries()); }

TEST(Recombination, RandomClassGridEveryHexFound) {
  const auto queries = hex_queries();
  for (std::uint32_t seed : {1u, 2u, 3u}) every_hex_found(random_grid(3, seed), queries);
}

TEST(Recombination, ScaledJacobian) {
  std::array<std::array<double, 3>, 8> cube{}, mirrored{}, sheared{};
  for (int v = 0; v < 8; ++v) {
    cube[static_cast<std::size_t>(v)] = {double(v & 1), double((v >> 1) & 1), double((v >> 2) & 1)};
    mirrored[static_cast<std::size_t>(v)] = {-double(v & 1), double((v >> 1) & 1), double((v >> 2) & 1)};
    sheared[static_cast<std::size_t>(v)] = {double(v & 1) + double((v >> 1) & 1), double((v >> 1) & 1), double((v >> 2) & 1)};
  }
  EXPECT_DOUBLE_EQ(scaled_jacobian(cube), 1.0);
  EXPECT_DOUBLE_EQ(scaled_jacobian(mirrored), 1.0);  // either handedness
  // A 45-degree shear: corners see edges (1,0,0), (1,1,0)/sqrt2, (0,0,1): 1/sqrt2.
  EXPECT_NEAR(scaled_jacobian(sheared), 1 / std::sqrt(2.0), 1e-12);
}

}  // namespace
}  // namespace dartcheck::querymodify::test
