// The cases of 000, rebuilt from its prose, with expectations derived by
// hand (cell counts by V/E/F reasoning, shapes from the shape builder), not
// from the tool's output.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "checkers/map_validity.hpp"
#include "core/isomorphism.hpp"
#include "inference_support.hpp"
#include "io/jerboa_jba.hpp"

namespace dartcheck::inference::test {
namespace {

const Operation& catalog_rule(const std::string& name) { return *seed_catalog().find_rule(name); }

std::vector<Attempt> infer_all(const Map& before, const Map& after, const KappaSpec& kappa, const std::string& orbit, FoldOptions fold = {}) {
  const auto graph = make_kappa_graph(before, after, kappa);
  InferOptions o;
  o.all = true;
  o.fold = fold;
  return infer(graph, parse_inference_orbit(orbit, before.model()), o);
}

const Attempt* first_inferred(const std::vector<Attempt>& attempts) {
  for (const auto& a : attempts)
    if (a.inferred()) return &a;
  return nullptr;
}

std::size_t count_inferred(const std::vector<Attempt>& attempts) {
  std::size_t n = 0;
  for (const auto& a : attempts) n += a.inferred();
  return n;
}

KappaSpec identity() {
  KappaSpec k;
  k.identity = true;
  return k;
}

// Sec. 4.4 and 9.1.1: the quad subdivision of the cube (Fig. 13) folds into
// the rule scheme of Fig. 14, the catalog's quad-subdivision-jerboa, up to
// node names; every start dart gives the same rule (L is one node).
TEST(InferenceCases, QuadSubdivisionOfTheCubeGivesFig14) {
  const Map cube = shape("cube");
  const auto& catalog = catalog_rule("quad-subdivision-jerboa");
  const Map after = applied(catalog, cube, 0);
  const auto attempts = infer_all(cube, after, identity(), "<0,1,2>");
  ASSERT_EQ(attempts.size(), 1u);  // the hook orbit is the whole cube
  const Attempt* a = first_inferred(attempts);
  ASSERT_NE(a, nullptr) << (attempts[0].failure ? attempts[0].failure->text : "");
  EXPECT_EQ(canonical_form(a->rule->operation), canonical_form(catalog));
  EXPECT_EQ(a->rule->operation.rule.left().node_count(), 1u);
  EXPECT_EQ(a->rule->operation.rule.right().node_count(), 4u);
  // Applied to a tetrahedron: V' = V + E + F = 4 + 6 + 4, E' = 2E + 3F = 24
  // (each edge halved, three new edges per triangle), F' = 3F = 12.
  const Map t = applied(a->rule->operation, shape("tetrahedron"), 0);
  EXPECT_TRUE(check_map(t).valid());
  EXPECT_EQ(count_cells(t).cells, (std::vector<std::size_t>{14, 24, 12}));
}

// Sec. 6.1: folding the cube along <1,2> (vertices) gives 8 nodes, one per
// vertex; the node of the opposite vertex, reached by 0 1 2 0 1 0 from the
// hook, relabels <1,2> to <2,1>; the node reached by 0 keeps 2 and deletes
// 1 (<_,2>).
TEST(InferenceCases, CubeFoldAlongVertices) {
  const Map cube = shape("cube");
  const auto graph = make_kappa_graph(cube, cube, identity());
  const auto folded = fold(graph, {1, 2}, 0);
  ASSERT_TRUE(folded.scheme) << folded.failure->text;
  const GraphScheme& s = *folded.scheme;
  std::size_t left = 0;
  for (const auto& n : s.nodes) left += !n.after;
  EXPECT_EQ(left, 8u);  // 48 darts / 6 per vertex
  auto step = [&](int m, Dim d) {
    for (const auto& a : s.arcs)
      if (a.d == d && (a.a == m || a.b == m)) return a.a == m ? a.b : a.a;
    return -1;
  };
  const int by0 = step(0, 0);
  ASSERT_GE(by0, 0);
  EXPECT_EQ(orbit_type_str(s.nodes[static_cast<std::size_t>(by0)].label), "<_,2>");
  int m = 0;
  for (Dim d : {0, 1, 2, 0, 1, 0}) {
    m = step(m, d);
    ASSERT_GE(m, 0) << "no " << d << "-arc";
  }
  EXPECT_EQ(orbit_type_str(s.nodes[static_cast<std::size_t>(m)].label), "<2,1>");
}

// Sec. 6.2, first counterexample: the pyramid folded along <1,2> from a
// corner of its base fails on a relabeling (a 1-link of the base corner's
// orbit becomes a non-link at the apex side).
TEST(InferenceCases, PyramidFromABaseCornerFailsOnARelabeling) {
  const Map pyramid = read_jba(std::string(DARTCHECK_SOURCE_DIR) + "/../shared/jerboa-samples/pyramid.jba").map;
  Dart base = no_dart, apex = no_dart;
  for (Dart d = 0; d < pyramid.size(); ++d) {
    const auto size = orbit_darts(pyramid, {1, 2}, d).size();
    if (size == 6 && base == no_dart) base = d;  // three faces meet at a base corner
    if (size == 8 && apex == no_dart) apex = d;  // four at the apex
  }
  ASSERT_NE(base, no_dart);
  ASSERT_NE(apex, no_dart);
  const auto graph = make_kappa_graph(pyramid, pyramid, identity());
  const auto from_base = fold(graph, {1, 2}, base, {.strict = true});
  ASSERT_TRUE(from_base.failure);
  EXPECT_EQ(from_base.failure->kind, FailureKind::relabeling) << from_base.failure->text;
}

// A cube without its last face, as a 2-G-map with a free border.
Map open_box() {
  auto faces = cube_faces();
  faces.pop_back();  // the cube without its last face: an open box
  return build_surface(Model::gmap(2), faces);
}

// Sec. 6.2, second counterexample: the open box folded along <0,2> from a
// vertical edge fails when building the explicit arcs: the node reached by
// 1 holds top darts (2-loops, the free border) and bottom darts (sewn to
// the bottom face).
TEST(InferenceCases, OpenBoxAlongAVerticalEdgeFailsOnAnInstantiation) {
  const Map box = open_box();
  // A vertical edge: its <0,2> orbit has 4 darts, and its 1-neighbours
  // include a dart with a 2-loop (the top border).
  Dart start = no_dart;
  for (Dart d = 0; d < box.size() && start == no_dart; ++d) {
    const auto orbit = orbit_darts(box, {0, 2}, d);
    if (orbit.size() != 4) continue;
    bool loop = false, sewn = false;
    for (Dart b : orbit) {
      const Dart c = box.link(1, b);
      (box.link(2, c) == c ? loop : sewn) = true;
    }
    if (loop && sewn) start = d;
  }
  ASSERT_NE(start, no_dart);
  const auto graph = make_kappa_graph(box, box, identity());
  const auto folded = fold(graph, {0, 2}, start, {.strict = true});
  ASSERT_TRUE(folded.failure);
  EXPECT_EQ(folded.failure->kind, FailureKind::instantiation) << folded.failure->text;
  EXPECT_EQ(folded.failure->dim, 2) << folded.failure->text;
}

// Sec. 8.2, Fig. 23: a triangle becomes a hexagon. Preserving the vertices
// (<1,2> orbits, corners 0, 2, 4 of the hexagon) is an edge split: a
// well-formed rule, which on the cube inserts a vertex in every edge
// (V' = V + E = 20, E' = 2E = 24, F' = 6). Preserving the edges (<0,2>) is
// a vertex split: the rule folds but breaks the cycle conditions, so no
// operation is inferred.
TEST(InferenceCases, TriangleToHexagonEdgeSplitAndVertexSplit) {
  const Map triangle = shape("polygon:3"), hexagon = shape("polygon:6");
  KappaSpec vertices, edges;
  for (int k = 0; k < 3; ++k) {
    vertices.orbits.push_back({{1, 2}, corner(triangle, k), corner(hexagon, 2 * k)});
    edges.orbits.push_back({{0, 2}, corner(triangle, k), corner(hexagon, 2 * k)});
  }
  const auto split_edges = infer_all(triangle, hexagon, vertices, "<0,1,2>");
  const Attempt* a = first_inferred(split_edges);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(count_inferred(split_edges), 1u);
  const Map cube = applied(a->rule->operation, shape("cube"), 0);
  EXPECT_TRUE(check_map(cube).valid());
  EXPECT_EQ(count_cells(cube).cells, (std::vector<std::size_t>{20, 24, 6}));

  const auto split_vertices = infer_all(triangle, hexagon, edges, "<0,1,2>");
  EXPECT_EQ(count_inferred(split_vertices), 0u);
  bool ill_formed = false;
  for (const auto& t : split_vertices) ill_formed |= !t.ill_formed.empty();
  EXPECT_TRUE(ill_formed) << "the vertex split should fold and be discarded by the checker";
}

// Sec. 10.2, Fig. 38: a square extruded into a cube, inferred on the face
// <0,1>, extrudes the triangle into the triangular prism and the octagon
// into the octagonal prism (isomorphic to the shape builder's prisms).
TEST(InferenceCases, FaceExtrusionFromSquareToCube) {
  const Map square = shape("polygon:4"), cube = shape("cube");
  // The square becomes one face of the cube: associate the faces.
  KappaSpec face;
  face.orbits.push_back({{0, 1}, 0, 0});
  const auto attempts = infer_all(square, cube, face, "<0,1>");
  const Attempt* a = first_inferred(attempts);
  ASSERT_NE(a, nullptr);
  for (int k : {3, 8}) {
    const Map prism = applied(a->rule->operation, shape(fmt::format("polygon:{}", k)), 0);
    EXPECT_TRUE(check_map(prism).valid());
    EXPECT_TRUE(isomorphic(prism, shape(fmt::format("prism:{}", k)))) << k;
    // V = 2k, E = 3k, F = k + 2.
    EXPECT_EQ(count_cells(prism).cells, (std::vector<std::size_t>{2u * k, 3u * k, k + 2u}));
  }
}

// κ must be a partial injective function between the two maps.
TEST(InferenceCases, KappaErrorsAreSentences) {
  const Map a = shape("polygon:3"), b = shape("polygon:4");
  KappaSpec k;
  k.pairs = {{0, 1}, {1, 1}};
  EXPECT_THROW(make_kappa_graph(a, b, k), ValueError);
  k.pairs = {{0, 99}};
  EXPECT_THROW(make_kappa_graph(a, b, k), ValueError);
  KappaSpec o;
  o.orbits.push_back({{0, 1}, 0, 0});  // a triangle's face is not a square's
  EXPECT_THROW(make_kappa_graph(a, b, o), ValueError);
  EXPECT_THROW(make_kappa_graph(a, build_shape(Model::omap(2), parse_shape("polygon:3")), KappaSpec{}), ValueError);
}

// A dart preserved for some darts of a node only: the node cannot be both
// kept and deleted (instantiation failure on κ).
TEST(InferenceCases, PartlyPreservedNodeIsAnInstantiationFailure) {
  const Map square = shape("polygon:4");
  KappaSpec k;
  k.pairs = {{0, 0}};
  const auto graph = make_kappa_graph(square, square, k);
  const auto folded = fold(graph, {0, 1, 2}, 0);
  ASSERT_TRUE(folded.failure);
  EXPECT_EQ(folded.failure->kind, FailureKind::instantiation);
  EXPECT_EQ(folded.failure->dim, kappa_arc);
}

// Two separate pieces cannot be one example: the folding names a dart it
// does not reach.
TEST(InferenceCases, DisconnectedExampleIsUnreached) {
  const Map square = shape("polygon:4");
  const auto graph = make_kappa_graph(square, square, KappaSpec{});  // nothing preserved
  const auto folded = fold(graph, {0, 1, 2}, 0);
  ASSERT_TRUE(folded.failure);
  EXPECT_EQ(folded.failure->kind, FailureKind::unreached);
}

// Undecided positions (every i-link of the hook orbit a loop): keep
// relabels and reports, free deletes with explicit loops, fail refuses.
// On the square (2-loops everywhere) quad subdivision leaves position 2
// undecided; the free variant then leaves the new faces' 2-links free on
// a closed cube, the kept one sews them.
TEST(InferenceCases, UndecidedPositionsFollowThePolicy) {
  const Map square = shape("polygon:4");
  const auto& catalog = catalog_rule("quad-subdivision-jerboa");
  const Map after = applied(catalog, square, 0);
  const auto graph = make_kappa_graph(square, after, identity());
  const std::vector<Dim> orbit{0, 1, 2};
  const auto kept = fold(graph, orbit, 0, {.undecided = UndecidedPolicy::keep});
  ASSERT_TRUE(kept.scheme);
  EXPECT_FALSE(kept.scheme->undecided.empty());
  const auto refused = fold(graph, orbit, 0, {.undecided = UndecidedPolicy::fail});
  ASSERT_TRUE(refused.failure);
  EXPECT_EQ(refused.failure->kind, FailureKind::undecided);
  const auto freed = fold(graph, orbit, 0, {.undecided = UndecidedPolicy::free});
  ASSERT_TRUE(freed.scheme);
  // Both fold the example back (App. A).
  for (const auto* s : {&*kept.scheme, &*freed.scheme}) {
    auto rule = to_rule(*s, graph.model(), "r");
    ASSERT_TRUE(rule.rule) << rule.why;
    EXPECT_TRUE(verify(graph, *s, *rule.rule, 0).holds);
  }
  EXPECT_NE(canonical_form(*kept.scheme), canonical_form(*freed.scheme));
}

}  // namespace
}  // namespace dartcheck::inference::test
