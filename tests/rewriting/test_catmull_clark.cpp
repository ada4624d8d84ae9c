// The subdivision catalog's Catmull-Clark (catmull-clark-points, then
// catmull-clark) on the cube [-1,1]^3, against the positions derived by
// hand from Catmull and Clark's rules:
//   face point   = centre of the face:            (1, 0, 0) and permutations;
//   edge point   = (A + B + F1 + F2) / 4, e.g. the edge (1,1,1)-(1,1,-1):
//                  ((2,2,0) + (1,0,0) + (0,1,0)) / 4 = (3/4, 3/4, 0);
//   vertex point = (Q + 2R + (n-3)V) / n with n = 3, e.g. V = (1,1,1):
//                  Q = (1/3, 1/3, 1/3), R = mean of (1,1,0), (1,0,1),
//                  (0,1,1) = (2/3, 2/3, 2/3): V' = (5/9, 5/9, 5/9).
// By symmetry every output vertex is a signed permutation of one of these.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <fmt/format.h>
#include <set>

#include <gtest/gtest.h>

#include "checkers/embedding_consistency.hpp"
#include "checkers/map_validity.hpp"
#include "core/orbit.hpp"
#include "generators/mesh_map.hpp"
#include "io/catalog.hpp"
#include "io/mesh_io.hpp"
#include "rewriting/application.hpp"
#include "tests/embedding_support.hpp"

namespace dartcheck {
namespace {

using testing_support::subdivision_catalog;

Mesh unit_cube() {
  Mesh m;
  m.file = "cube";
  for (int k = 0; k < 8; ++k) m.positions.push_back({k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0});
  // Outward-oriented quads (vertex k = (x, y, z) bits).
  m.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return m;
}

// The cube with pos from the mesh and empty fpt and emid.
EmbeddedMap cube_map() {
  const auto& sigs = subdivision_catalog().signatures;
  EmbeddedMap g = mesh_with_positions(Model::gmap(2), unit_cube(), sigs[0]);
  for (std::size_t k = 1; k < sigs.size(); ++k) g.add_embedding(sigs[k]);
  return g;
}

// The positions of the vertices (<1,2>-orbits), sorted after rounding the
// absolute coordinates to 1e-9 (the symmetry classes of the cube).
std::multiset<std::array<long, 3>> vertex_classes(const EmbeddedMap& g) {
  OrbitWalker walker(g.map);
  std::vector<bool> seen(g.map.size());
  std::multiset<std::array<long, 3>> out;
  for (Dart d = 0; d < g.map.size(); ++d) {
    if (seen[d]) continue;
    for (Dart x : walker.orbit(d, dims_generators({1, 2}))) seen[x] = true;
    const Value* v = g.embeddings[0].value(d);
    if (!v) {
      ADD_FAILURE() << "dart " << d << " has no position";
      continue;
    }
    std::array<long, 3> c{};
    for (std::size_t k = 0; k < 3; ++k) c[k] = std::lround(std::abs(v->x[k]) * 1e9);
    std::sort(c.begin(), c.end());
    out.insert(c);
  }
  return out;
}

TEST(CatmullClark, CubeGetsTheHandDerivedPoints) {
  for (Evaluation e : {Evaluation::every_instance, Evaluation::one_per_orbit}) {
    EmbeddedMap g = cube_map();
    const Dart hook = 0;
    for (const char* name : {"catmull-clark-points", "catmull-clark"}) {
      const Operation& r = *subdivision_catalog().find_rule(name);
      Applier rewriter(r, {e});
      const auto d = rewriter.apply(g, std::span(&hook, 1));
      ASSERT_TRUE(d.ok()) << name << ": " << d.why;
      EXPECT_TRUE(d.value->conflicts.empty()) << name;
    }
    ASSERT_TRUE(check_map(g.map).valid());
    for (const Embedding& x : g.embeddings) EXPECT_TRUE(check_embedding(g.map, x, true).consistent()) << x.signature.name;
    // V + E + F = 8 + 12 + 6 vertices, 2E + 4F = 48 edges, 4F = 24 quads.
    EXPECT_EQ(count_cells(g.map).cells, (std::vector<std::size_t>{26, 48, 24}));
    const long one = 1000000000, three_quarters = 750000000, five_ninths = 555555556;
    std::multiset<std::array<long, 3>> want;
    for (int k = 0; k < 6; ++k) want.insert({0, 0, one});                              // face points
    for (int k = 0; k < 12; ++k) want.insert({0, three_quarters, three_quarters});     // edge points
    for (int k = 0; k < 8; ++k) want.insert({five_ninths, five_ninths, five_ninths});  // vertex points
    EXPECT_EQ(vertex_classes(g), want);
  }
}

// A rule that writes an embedding the map does not have is refused with
// its name, not applied halfway.
TEST(CatmullClark, MissingHelperEmbeddingIsRefused) {
  EmbeddedMap g = mesh_with_positions(Model::gmap(2), unit_cube(), subdivision_catalog().signatures[0]);
  const Map before = g.map;
  const Operation& r = *subdivision_catalog().find_rule("catmull-clark-points");
  const Dart hook = 0;
  const auto d = Applier(r).apply(g, std::span(&hook, 1));
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.refusal, Refusal::no_value);
  EXPECT_NE(d.why.find("fpt"), std::string::npos) << d.why;
  EXPECT_EQ(g.map, before);
}

// An R term `x.pi` for its own embedding pi takes the stored value of x's
// dart without evaluation (as catmull-clark's helper labels n0.fpt do).
// Where that dart has no value, evaluating every instance refuses the
// application as an evaluated term would be (003 Def. 10: the term has no
// value) and leaves the map unchanged. (One evaluation per orbit reads one
// instance per class, so it labels a partly labeled orbit from the
// instance it reads: such a map is outside 003's theorems.) Where the
// face has a value, both keep it.
TEST(EmbeddedApplication, OwnAccessWithoutValueIsRefused) {
  const auto file = std::filesystem::temp_directory_path() / fmt::format("dartcheck-own-access-{}.yaml", ::getpid());
  {
    std::ofstream out(file);
    out << "model: 2-gmap\n"
           "embeddings:\n  - {name: col, type: color, orbit: \"<0,1>\"}\n"
           "rules:\n  - name: keep-colour\n    embeddings: [col]\n    hooks: [n0]\n"
           "    left: {nodes: {n0: \"<0,1>\"}}\n    right: {nodes: {n0: \"<0,1>\"}}\n"
           "    labels:\n      right: {n0: {col: \"n0.col\"}}\n";
  }
  const Catalog c = read_catalog(file.string());
  std::filesystem::remove(file);
  const CatalogRule& r = *c.find_rule("keep-colour");
  Mesh square;
  square.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  square.faces = {{0, 1, 2, 3}};
  for (Evaluation e : {Evaluation::every_instance, Evaluation::one_per_orbit}) {
    EmbeddedMap g(build_mesh(Model::gmap(2), square));
    g.add_embedding(c.signatures[0]);
    g.embeddings[0].set(0, Value::coords(ValueType::color, {1, 0, 0}));  // dart 0 only
    const EmbeddedMap before = g;
    const Dart hook = 0;
    if (e == Evaluation::every_instance) {
      const auto d = Applier(r, {e}).apply(g, std::span(&hook, 1));
      ASSERT_FALSE(d.ok());
      EXPECT_EQ(d.refusal, Refusal::no_value);
      EXPECT_NE(d.why.find("n0.col: dart 1 has no col value"), std::string::npos) << d.why;
      EXPECT_EQ(g.map, before.map);
      for (Dart x = 0; x < g.map.size(); ++x) EXPECT_EQ(g.embeddings[0].value(x) != nullptr, x == 0);
    }
    g.label_orbit(0, 0, Value::coords(ValueType::color, {0, 1, 0}));
    const auto d = Applier(r, {e}).apply(g, std::span(&hook, 1));
    ASSERT_TRUE(d.ok()) << d.why;
    for (Dart x = 0; x < g.map.size(); ++x) EXPECT_EQ(*g.embeddings[0].value(x), Value::coords(ValueType::color, {0, 1, 0}));
  }
}

}  // namespace
}  // namespace dartcheck
