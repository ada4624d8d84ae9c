#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>
#include <utility>

#include "checkers/map_validity.hpp"
#include "io/catalog.hpp"
#include "rewriting/detail/derivation.hpp"
#include "core/isomorphism.hpp"
#include "core/orbit.hpp"
#include "generators/random_maps.hpp"
#include "tests/map_recipe_gen.hpp"
#include "generators/shapes.hpp"

using namespace dartcheck;

namespace {
const Catalog& seed() {
  static const Catalog c = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  return c;
}
const Rule& seed_rule(const std::string& name) { return seed().find_rule(name)->rule; }

TopoGraph side(std::vector<std::string> nodes, std::vector<std::tuple<int, int, int>> arcs) {
  TopoGraph g;
  for (auto& n : nodes) g.add_node(n);
  for (auto [s, t, l] : arcs) g.add_arc(static_cast<NodeId>(s), static_cast<NodeId>(t), l);
  return g;
}
}  // namespace

// Assumption 2: K = L ∩ R, arcs counted with multiplicity.
TEST(Rule, InterfaceIsTheIntersectionWithMultiplicity) {
  Rule r("r", Model::gmap(2), side({"a", "b"}, {{0, 1, 0}, {0, 1, 0}, {1, 0, 0}}), side({"b", "a", "c"}, {{1, 0, 0}, {0, 2, 1}}), {"a"});
  EXPECT_EQ(r.to_right(0), 1u);
  EXPECT_EQ(r.to_right(1), 0u);
  EXPECT_EQ(r.to_left(2), no_node);
  EXPECT_TRUE(r.preserved_left_arc(0));
  EXPECT_FALSE(r.preserved_left_arc(1)) << "only one of the two parallel arcs is in R";
  EXPECT_FALSE(r.preserved_left_arc(2));
  EXPECT_TRUE(r.preserved_right_arc(0));
  EXPECT_FALSE(r.preserved_right_arc(1));
}

TEST(Rule, HooksOnePerComponent) {
  auto two = side({"a", "b"}, {});
  EXPECT_THROW(Rule("r", Model::gmap(2), two, two, {"a"}), ValueError) << "b's component has no hook";
  EXPECT_NO_THROW(Rule("r", Model::gmap(2), two, two, {"a", "b"}));
  auto one = side({"a", "b"}, {{0, 1, 0}});
  EXPECT_THROW(Rule("r", Model::gmap(2), one, one, {"a", "b"}), ValueError);
  EXPECT_THROW(Rule("r", Model::gmap(2), one, one, {"z"}), ValueError);
  EXPECT_THROW(Rule("r", Model::gmap(2), side({"a"}, {{0, 0, 3}}), side({"a"}, {}), {"a"}), ValueError) << "3 is not in [0,2]";
}

// 000 Fig. 7(a) on the square of polygon_faces(4): darts 2e, 2e+1 are side e.
// From x = 0: y = alpha0(0) = 1; R adds a, b as darts 8, 9 with
// 0 -0- 8 -1- 9 -0- 1, and 2-loops on 8 and 9. Derived by hand.
TEST(Derivation, InsertVertexOnFreeEdgeByHand) {
  Map g = build_shape(Model::gmap(2), {"polygon", {4}});
  const Dart hook = 0;
  auto out = apply_rule(seed_rule("insert-vertex-free-edge"), g, std::span(&hook, 1));
  ASSERT_TRUE(out.ok()) << out.why;
  ASSERT_EQ(g.size(), 10u);
  EXPECT_EQ(g.link(0, 0), 8u);
  EXPECT_EQ(g.link(0, 8), 0u);
  EXPECT_EQ(g.link(1, 8), 9u);
  EXPECT_EQ(g.link(1, 9), 8u);
  EXPECT_EQ(g.link(0, 9), 1u);
  EXPECT_EQ(g.link(0, 1), 9u);
  EXPECT_EQ(g.link(2, 8), 8u);
  EXPECT_EQ(g.link(2, 9), 9u);
  EXPECT_EQ(g.link(1, 1), 2u) << "the rest of the face is untouched";
  EXPECT_TRUE(check_map(g).valid());
}

TEST(Derivation, RefusalLeavesTheMapUnchanged) {
  Map g = build_shape(Model::gmap(2), {"cube", {}});
  const Map before = g;
  const Dart hook = 3;
  auto out = apply_rule(seed_rule("insert-vertex-free-edge"), g, std::span(&hook, 1));
  EXPECT_FALSE(out.ok());
  EXPECT_EQ(out.refusal, Refusal::no_match);
  EXPECT_EQ(g, before);
  auto dangling = apply_rule(seed_rule("delete-free-edge-dangling"), g = build_shape(Model::gmap(2), {"polygon", {4}}), std::span(&hook, 1));
  EXPECT_EQ(dangling.refusal, Refusal::dangling);
  EXPECT_EQ(g, build_shape(Model::gmap(2), {"polygon", {4}}));
}

// Deleting darts leaves no hole: the last darts move into the freed slots
// and every arc pointing at them follows.
TEST(Derivation, DeletionKeepsTheMapDense) {
  // A lone edge (darts 0, 1) then a square (darts 2..9).
  Map g(Model::gmap(2), 2);
  g.sew(0, 0, 1);
  for (Dim i : {1, 2})
    for (Dart d : {0u, 1u}) g.sew(i, d, d);
  Map square = build_shape(Model::gmap(2), {"polygon", {4}});
  const Dart base = g.add_darts(square.size());
  for (Dim i : {0, 1, 2})
    for (Dart d = 0; d < square.size(); ++d) g.sew(i, base + d, base + square.link(i, d));
  const Dart hook = 0;
  auto out = apply_rule(seed_rule("delete-isolated-edge"), g, std::span(&hook, 1));
  ASSERT_TRUE(out.ok()) << out.why;
  EXPECT_EQ(g.size(), 8u);
  EXPECT_EQ(out.value->moved.size(), 2u);
  EXPECT_TRUE(check_map(g).valid());
  EXPECT_TRUE(isomorphic(g, square));
}

// Regression (found by GraphDerivation.AgreesWithDenseEngine): deleting
// four darts whose slots interleave with the last darts once dropped a live
// dart. Two digons sewn into a sphere (V = 2, E = 2, F = 2); removing one
// degree-2 vertex leaves one vertex, one loop edge and two faces on 4 darts.
TEST(Derivation, DeletionWithInterleavedHoles) {
  Map sphere(Model::gmap(2), 8);
  for (auto [a, b] : {std::pair{0, 1}, {2, 3}, {4, 5}, {6, 7}}) sphere.sew(0, a, b);
  for (auto [a, b] : {std::pair{0, 3}, {1, 2}, {4, 7}, {5, 6}}) sphere.sew(1, a, b);
  for (auto [a, b] : {std::pair{0, 5}, {1, 4}, {2, 7}, {3, 6}}) sphere.sew(2, a, b);
  ASSERT_TRUE(check_map(sphere).valid());
  ASSERT_EQ(count_cells(sphere).cells, (std::vector<std::size_t>{2, 2, 2}));
  for (Dart hook : {0u, 1u}) {
    Map g = sphere;
    auto out = apply_rule(seed_rule("remove-vertex-sewn-edge"), g, std::span(&hook, 1));
    ASSERT_TRUE(out.ok()) << out.why;
    EXPECT_EQ(g.size(), 4u);
    EXPECT_TRUE(check_map(g).valid());
    EXPECT_EQ(count_cells(g).cells, (std::vector<std::size_t>{1, 1, 2}));
  }
}

// Property (issue 2): on random valid maps, a rule followed by its inverse
// gives back an isomorphic map; a refused application changes nothing.
// For the edge split of 000 Fig. 7(c) and its O-map counterpart, every
// application adds exactly one vertex and one edge (hand derivation: the new
// darts form one <1,2>-orbit; the <0,2>-orbit of the edge splits in two;
// faces only grow).
RC_GTEST_PROP(Derivation, RuleThenInverseIsIdentityUpToIsomorphism, ()) {
  const bool gmap = *rc::gen::arbitrary<bool>();
  const Model model = gmap ? Model::gmap(2) : Model::omap(2);
  const Rule& rule = seed_rule(gmap ? "insert-vertex-sewn-edge" : "split-edge-omap");
  const Map original = build_random_map(model, *gen_map_recipe(1, 25));
  RC_PRE(original.size() > 0);
  const Dart hook = *rc::gen::inRange<Dart>(0, static_cast<Dart>(original.size()));
  Map g = original;
  auto out = apply_rule(rule, g, std::span(&hook, 1));
  if (!out.ok()) {
    RC_ASSERT(g == original);
    RC_TAG("refused");
    return;
  }
  RC_ASSERT(check_map(g).valid());
  auto before = count_cells(original).cells, after = count_cells(g).cells;
  RC_ASSERT(after[0] == before[0] + 1);
  RC_ASSERT(after[1] == before[1] + 1);
  RC_ASSERT(after[2] == before[2]);
  const Rule inverse = rule.inverse({"x"});
  const Dart back = out.value->comatch[*rule.right().find("x")];
  auto undo = apply_rule(inverse, g, std::span(&back, 1));
  RC_ASSERT(undo.ok());
  RC_ASSERT(isomorphic(g, original));
}

TEST(Isomorphism, DistinguishesAndIdentifies) {
  Map a = build_shape(Model::gmap(2), {"cube", {}});
  Map b = build_shape(Model::gmap(2), {"prism", {4}});
  EXPECT_TRUE(isomorphic(a, b)) << "a 4-prism is a cube";
  EXPECT_FALSE(isomorphic(a, build_shape(Model::gmap(2), {"prism", {5}})));
  Map c = a;
  c.sew(2, 0, 0);
  EXPECT_FALSE(isomorphic(a, c));
}
