// 000 Sec. 9.1: subdivision schemes inferred from one small example and
// applied to other meshes. Expectations come from soup_subdivision.hpp,
// the same topologies written face by face (an oracle that shares nothing
// with the folding), compared by isomorphism rooted at the hook dart and
// its image, and from cell counts derived by hand.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "checkers/map_validity.hpp"
#include "core/isomorphism.hpp"
#include "inference_support.hpp"
#include "io/mesh_io.hpp"
#include "soup_subdivision.hpp"

namespace dartcheck::inference::test {
namespace {

using Subdivision = Subdivided (*)(const std::vector<Polygon>&);

const Model gmap2 = Model::gmap(2);

// κ(G, H) of the oracle on `faces`, and the inferred rule (first start).
Attempt infer_from(const std::vector<Polygon>& faces, Subdivision subdivide) {
  const Subdivided s = subdivide(faces);
  KappaSpec k;
  for (const auto& [b, a] : s.kappa) k.pairs.emplace_back(soup_dart(faces, b), soup_dart(s.faces, a));
  const auto graph = make_kappa_graph(build_surface(gmap2, faces), build_surface(gmap2, s.faces), k);
  auto attempts = infer(graph, {0, 1, 2}, {});
  for (auto& a : attempts)
    if (a.inferred()) return std::move(a);
  ADD_FAILURE() << "nothing inferred: " << (attempts.back().failure ? attempts.back().failure->text : attempts.back().not_a_rule);
  return {};
}

// The rule applied to `faces` at dart 0 equals the oracle's subdivision.
void expect_like_oracle(const Attempt& a, const std::vector<Polygon>& faces, Subdivision subdivide, const std::string& what) {
  ASSERT_TRUE(a.rule);
  const Map h = applied(a.rule->operation, build_surface(gmap2, faces), 0);
  ASSERT_TRUE(check_map(h).valid()) << what;
  const Subdivided s = subdivide(faces);
  const Map oracle = build_surface(gmap2, s.faces);
  ASSERT_EQ(h.size(), oracle.size()) << what;
  // Dart 0 is preserved by the rule (nothing is deleted, so nothing is
  // renumbered); the oracle sends it to its κ image.
  const SoupDart zero{0, faces[0][0], faces[0][1]};
  Dart root = no_dart;
  for (const auto& [b, after] : s.kappa)
    if (b.face == zero.face && b.at == zero.at && b.to == zero.to) root = soup_dart(s.faces, after);
  ASSERT_NE(root, no_dart);
  EXPECT_EQ(component_code(h, 0), component_code(oracle, root)) << what;
}

std::vector<Polygon> triangle() { return {{0, 1, 2}}; }

std::vector<Polygon> mesh_faces(const std::string& name) { return read_mesh(std::string(DARTCHECK_MESH_DIR) + "/" + name).faces; }

// Quad subdivision from the cube (Fig. 13), applied to the tetrahedron,
// the octahedron and CGAL's quad torus. Tetrahedron by hand: V' = V + E + F
// = 14, E' = 2E + sum of face degrees = 12 + 12 = 24, F' = 12.
TEST(SubdivisionInference, QuadFromTheCube) {
  const Attempt a = infer_from(cube_faces(), quad_subdivision);
  expect_like_oracle(a, tetrahedron_faces(), quad_subdivision, "tetrahedron");
  expect_like_oracle(a, octahedron_faces(), quad_subdivision, "octahedron");
  expect_like_oracle(a, mesh_faces("torus_quad.off"), quad_subdivision, "torus_quad.off");
  const Map t = applied(a.rule->operation, build_surface(gmap2, tetrahedron_faces()), 0);
  EXPECT_EQ(count_cells(t).cells, (std::vector<std::size_t>{14, 24, 12}));
}

// Loop from one triangle (Fig. 27: the paper infers it so). The triangle's
// 2-links are loops, so position 2 of some nodes is undecided; the rule
// keeps the relabeling and is right on closed meshes. Tetrahedron by hand:
// V' = V + E = 10, E' = 2E + 3F = 24, F' = 4F = 16.
TEST(SubdivisionInference, LoopFromOneTriangle) {
  const Attempt a = infer_from(triangle(), loop_subdivision);
  ASSERT_TRUE(a.scheme);
  EXPECT_FALSE(a.scheme->undecided.empty());
  EXPECT_EQ(a.rule->operation.rule.right().node_count(), 4u);  // four darts per old dart: F' = 4F
  expect_like_oracle(a, tetrahedron_faces(), loop_subdivision, "tetrahedron");
  expect_like_oracle(a, icosahedron_faces(), loop_subdivision, "icosahedron");
  expect_like_oracle(a, mesh_faces("elephant.off"), loop_subdivision, "elephant.off");
  const Map t = applied(a.rule->operation, build_surface(gmap2, tetrahedron_faces()), 0);
  EXPECT_EQ(count_cells(t).cells, (std::vector<std::size_t>{10, 24, 16}));
}

// Powell-Sabin 6-split from one triangle (Fig. 29). Tetrahedron by hand:
// V' = V + E + F = 14, E' = 2E + 6F = 36, F' = 6F = 24. Sec. 10.1: the rule
// does not know it was inferred on a triangle; on the cube it splits each
// quad into 8 triangles (V' = 8 + 12 + 6, F' = 48).
TEST(SubdivisionInference, PowellSabinFromOneTriangle) {
  const Attempt a = infer_from(triangle(), powell_sabin);
  expect_like_oracle(a, tetrahedron_faces(), powell_sabin, "tetrahedron");
  expect_like_oracle(a, octahedron_faces(), powell_sabin, "octahedron");
  expect_like_oracle(a, cube_faces(), powell_sabin, "cube");
  const Map t = applied(a.rule->operation, build_surface(gmap2, tetrahedron_faces()), 0);
  EXPECT_EQ(count_cells(t).cells, (std::vector<std::size_t>{14, 36, 24}));
  const Map c = applied(a.rule->operation, build_surface(gmap2, cube_faces()), 0);
  EXPECT_EQ(count_cells(c).cells, (std::vector<std::size_t>{26, 72, 48}));
}

// Kobbelt's sqrt(3) from the tetrahedron (Fig. 31). It flips the old
// edges, so the old darts change role: the preserved node relabels <0,1,2>
// to <_,2,1> (old 1-links become 2-links and back). Tetrahedron by hand:
// V' = V + F = 8, E' = E + 3F = 18 (each old edge is replaced by its
// flip, each face adds three), F' = 3F = 12.
TEST(SubdivisionInference, Sqrt3FromTheTetrahedron) {
  const Attempt a = infer_from(tetrahedron_faces(), sqrt3);
  ASSERT_TRUE(a.rule);
  EXPECT_EQ(orbit_type_str(a.rule->operation.jerboa->right[0]), "<_,2,1>");
  expect_like_oracle(a, octahedron_faces(), sqrt3, "octahedron");
  expect_like_oracle(a, icosahedron_faces(), sqrt3, "icosahedron");
  expect_like_oracle(a, mesh_faces("elephant.off"), sqrt3, "elephant.off");
  const Map t = applied(a.rule->operation, build_surface(gmap2, tetrahedron_faces()), 0);
  EXPECT_EQ(count_cells(t).cells, (std::vector<std::size_t>{8, 18, 12}));
}

Subdivided doo_sabin_2(const std::vector<Polygon>& f) { return iterate(doo_sabin(f), doo_sabin); }
Subdivided doo_sabin_3(const std::vector<Polygon>& f) { return iterate(iterate(doo_sabin(f), doo_sabin), doo_sabin); }

// Doo-Sabin from the cube (Fig. 33), and the rules of its second and third
// iterations inferred directly (Fig. 32: self-composition). By hand: every
// new vertex has degree 4 and is a corner of one old face, so V' = the sum
// of face degrees = 2E, E' = 2V', F' = F + E + V. Cube: (8, 12, 6) ->
// (24, 48, 26) -> (96, 192, 98) -> (384, 768, 386).
TEST(SubdivisionInference, DooSabinIterationsFromTheCube) {
  const Attempt one = infer_from(cube_faces(), doo_sabin);
  expect_like_oracle(one, tetrahedron_faces(), doo_sabin, "tetrahedron");
  expect_like_oracle(one, mesh_faces("torus_quad.off"), doo_sabin, "torus_quad.off");
  const Map c1 = applied(one.rule->operation, build_surface(gmap2, cube_faces()), 0);
  EXPECT_EQ(count_cells(c1).cells, (std::vector<std::size_t>{24, 48, 26}));
  const Attempt two = infer_from(cube_faces(), doo_sabin_2);
  const Attempt three = infer_from(cube_faces(), doo_sabin_3);
  ASSERT_TRUE(two.rule && three.rule);
  const Map c2 = applied(two.rule->operation, build_surface(gmap2, cube_faces()), 0);
  EXPECT_EQ(count_cells(c2).cells, (std::vector<std::size_t>{96, 192, 98}));
  const Map c3 = applied(three.rule->operation, build_surface(gmap2, cube_faces()), 0);
  EXPECT_EQ(count_cells(c3).cells, (std::vector<std::size_t>{384, 768, 386}));
  // The third iteration's rule on the octahedron is Doo-Sabin three times.
  expect_like_oracle(three, octahedron_faces(), doo_sabin_3, "octahedron");
  // |R| = darts after / darts before: 48 -> 3072 darts.
  EXPECT_EQ(three.rule->operation.rule.right().node_count(), 64u);
}

}  // namespace
}  // namespace dartcheck::inference::test
