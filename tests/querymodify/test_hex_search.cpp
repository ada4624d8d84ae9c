// The vertex search of the recombination (hex_search.hpp) against 001's
// word search, its definition. Theorem tested: on a tetrahedral mesh, the
// sets of tetrahedra the vertex search returns are exactly those of the
// word search's distinct matches whose 8 query corners fall on 8 distinct
// mesh vertices, and each candidate's quality is the best scaled Jacobian
// over its query's readings. Meshes: hex grids where one hex is a random
// member of each of the 174 classes (under a random vertex numbering and
// tetrahedron order), random-class grids, and (a ctest with tetgen's
// elephant) a real mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <numeric>
#include <optional>
#include <random>
#include <set>

#include "grid_tets.hpp"
#include "io/tet_mesh_io.hpp"
#include "querymodify/hex_search.hpp"
#include "querymodify/overlap.hpp"
#include "querymodify/recombination.hpp"

namespace dartcheck::querymodify::test {
namespace {

using Tets = std::vector<std::array<std::uint32_t, 4>>;
using Points = std::vector<std::array<double, 3>>;
// Each candidate by its sorted tetrahedra: its quality (NaN without points).
using Found = std::map<std::vector<std::uint32_t>, double>;

// The word search's side, computed from the matches alone: a match's
// corners under the query's reading, the best scaled Jacobian over all
// readings.
Found by_words(const Tets& tets, const Points* points) {
  const TetMap mesh = build_tet_map(tets);
  const auto& queries = hex_queries();
  QueryTrie trie;
  for (std::size_t k = 0; k < queries.size(); ++k) trie.add(queries[k].word, static_cast<int>(k));
  std::uint32_t vertices = 0;
  for (auto v : mesh.vertex) vertices = std::max(vertices, v + 1);
  std::vector<std::uint32_t> count(vertices, 0);
  const ClassBound bound{&mesh.vertex, 8, &count};
  Found out;
  for (const auto& m : all_matches(mesh.map, trie, &bound, 1).distinct) {
    const HexQuery& q = queries[static_cast<std::size_t>(m.query)];
    const auto c = match_corners(q, query_corners(q), m, mesh.vertex);
    if (std::set<std::uint32_t>(c.begin(), c.end()).size() < 8) continue;
    std::vector<std::uint32_t> key;
    for (Dart d : m.darts) key.push_back(d / 12);
    std::sort(key.begin(), key.end());
    key.erase(std::unique(key.begin(), key.end()), key.end());
    double best = std::nan("");
    if (points)
      for (const auto& reading : q.readings) {
        std::array<std::uint32_t, 8> corners{};
        for (std::size_t v = 0; v < 8; ++v) corners[reading[v]] = c[v];
        const double j = scaled_jacobian(corner_points(corners, *points));
        if (!(j <= best)) best = j;
      }
    EXPECT_FALSE(out.count(key)) << "two distinct matches on the same tetrahedra";
    out[key] = best;
  }
  return out;
}

Found by_vertices(const Tets& tets, const Points* points) {
  const HexCandidates c = find_hex_candidates(tets, points);
  Found out;
  for (const auto& h : c.list) {
    const auto t = c.tets_of(h);
    std::vector<std::uint32_t> key(t.begin(), t.end());
    EXPECT_TRUE(std::is_sorted(key.begin(), key.end()));
    EXPECT_FALSE(out.count(key)) << "a candidate listed twice";
    // Its corners hold exactly its tetrahedra's vertices.
    std::set<std::uint32_t> on;
    for (auto x : key) on.insert(tets[x].begin(), tets[x].end());
    EXPECT_EQ(on, std::set<std::uint32_t>(h.corners.begin(), h.corners.end()));
    out[key] = h.quality;
  }
  return out;
}

void expect_same(const Tets& tets, const Points* points, const std::string& what) {
  const Found words = by_words(tets, points), vertices = by_vertices(tets, points);
  std::size_t missing = 0, extra = 0;
  for (const auto& [key, q] : words) missing += !vertices.count(key);
  for (const auto& [key, q] : vertices) extra += !words.count(key);
  EXPECT_EQ(missing, 0u) << what << ": word matches the vertex search did not find";
  EXPECT_EQ(extra, 0u) << what << ": vertex candidates no word matches";
  EXPECT_GT(words.size(), 0u) << what;
  if (!points) return;
  for (const auto& [key, q] : words) {
    const auto it = vertices.find(key);
    if (it == vertices.end()) continue;
    // The same readings up to the cube's symmetries, and the scaled
    // Jacobian gives every symmetric image of a reading the same bits.
    EXPECT_EQ(it->second, q) << what;
  }
}

// The mesh renumbered: vertices by a random permutation, tetrahedra
// shuffled, each tetrahedron's vertices rotated (the search must not lean
// on any order).
void shuffle(Tets& tets, Points& points, std::mt19937& rng) {
  std::vector<std::uint32_t> to(points.size());
  std::iota(to.begin(), to.end(), 0);
  std::shuffle(to.begin(), to.end(), rng);
  Points moved(points.size());
  for (std::size_t v = 0; v < points.size(); ++v) moved[to[v]] = points[v];
  points = moved;
  for (auto& t : tets) {
    for (auto& v : t) v = to[v];
    std::rotate(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(rng() % 4), t.end());
  }
  std::shuffle(tets.begin(), tets.end(), rng);
}

// True if the grid is a mesh (no triangle in three tetrahedra).
bool is_mesh(const HexGrid& g) {
  try {
    build_tet_map(g.tets);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

TEST(HexSearch, EveryClassAmongRandomNeighbours) {
  // One random labeled member of each class (the full symmetry group's
  // orbits of labeled subdivisions).
  std::map<std::uint64_t, std::vector<std::uint64_t>> classes;
  for (auto s : enumerate_hex_subdivisions()) classes[canonical_subdivision(s)].push_back(s);
  ASSERT_EQ(classes.size(), 174u);
  std::mt19937 rng(40);
  std::size_t grids = 0;
  for (const auto& [canonical, members] : classes) {
    const std::uint64_t member = members[rng() % members.size()];
    HexGrid g = random_hexes(2, rng, member);
    if (!is_mesh(g)) continue;
    shuffle(g.tets, g.points, rng);
    expect_same(g.tets, &g.points, "class " + std::to_string(canonical));
    ++grids;
    if (HasFailure()) break;
  }
  EXPECT_EQ(grids, 174u);
}

TEST(HexSearch, RandomClassGrids) {
  std::mt19937 rng(7);
  int grids = 0;
  for (int attempt = 0; grids < 4 && attempt < 40; ++attempt) {
    HexGrid g = random_hexes(3, rng);
    if (!is_mesh(g)) continue;
    shuffle(g.tets, g.points, rng);
    expect_same(g.tets, &g.points, "random grid " + std::to_string(attempt));
    expect_same(g.tets, nullptr, "random grid without points " + std::to_string(attempt));
    ++grids;
  }
  EXPECT_EQ(grids, 4);
}

// Run by ctest with tetgen's elephant (tests/CMakeLists.txt): the mesh in
// DARTCHECK_TET_MESH.
TEST(HexSearchRealMesh, DISABLED_SameCandidatesAsWords) {
  const char* file = std::getenv("DARTCHECK_TET_MESH");
  ASSERT_NE(file, nullptr) << "set DARTCHECK_TET_MESH to a tetrahedral mesh";
  const TetMesh mesh = read_tet_mesh(file);
  expect_same(mesh.tets, &mesh.points, file);
  RecordProperty("tetrahedra", static_cast<int>(mesh.tets.size()));
}

}  // namespace
}  // namespace dartcheck::querymodify::test
