// 000 Sec. 9.2: volume refinements on 3-G-maps, inferred on <0,1,2,3> from
// a cube. The after maps are polycubes built cube by cube (build_volumes,
// which 3-sews the shared squares), an oracle independent of the folding;
// the counts are derived by hand in the comments.
#include <gtest/gtest.h>

#include <array>
#include <functional>

#include "checkers/map_validity.hpp"
#include "core/isomorphism.hpp"
#include "inference_support.hpp"
#include "io/jerboa_jba.hpp"
#include "polycube.hpp"

namespace dartcheck::inference::test {
namespace {

std::size_t boundary_faces(const Map& g) {
  // Faces <0,1> whose darts carry 3-loops: one per boundary square.
  std::size_t loops = 0;
  for (Dart d = 0; d < g.size(); ++d) loops += g.link(3, d) == d;
  return loops / 8;  // 8 darts per square
}

// Infers the refinement on <0,1,2,3> from the coarse polycube to its
// refinement.
Attempt infer_refinement(const std::vector<std::array<std::uint32_t, 3>>& coarse, std::uint32_t coarse_n, std::uint32_t n, const Keep& keep) {
  const auto fine = refine(coarse, coarse_n, n, keep);
  const auto graph = make_kappa_graph(polycube(coarse, coarse_n), polycube(fine, n * coarse_n), corner_kappa(coarse, coarse_n, fine, n));
  auto attempts = infer(graph, {0, 1, 2, 3}, {});
  for (auto& a : attempts)
    if (a.inferred()) return std::move(a);
  ADD_FAILURE() << "nothing inferred: " << (attempts.back().failure ? attempts.back().failure->text : attempts.back().not_a_rule);
  return {};
}

const std::vector<std::array<std::uint32_t, 3>> one_cube{{0, 0, 0}};
const std::vector<std::array<std::uint32_t, 3>> two_cubes{{0, 0, 0}, {1, 0, 0}};

// Menger, level 1 (Sec. 9.2.1): the 27 cubes of a 3-grid minus the centre
// and the 6 face centres. By hand: the 4^3 = 64 lattice points and all 144
// lattice edges are used; of the 108 lattice squares, the 6 between the
// centre and the face centres and the 6 outer squares of the face centres
// touch no kept cube: 96 faces. Volumes 20. 20 x 6 = 120 = 2I + B with
// I + B = 96: B = 72 boundary squares. Solid Euler 64 - 144 + 96 - 20 = -4
// = 1 - g: genus 5. The same map as Jerboa's cube-frame.jba.
TEST(VolumeInference, MengerLevelOneIsCubeFrame) {
  const auto level1 = refine(one_cube, 1, 3, menger_local);
  const Map after = polycube(level1, 3);
  ASSERT_TRUE(check_map(after).valid());
  EXPECT_EQ(count_cells(after).cells, (std::vector<std::size_t>{64, 144, 96, 20}));
  EXPECT_EQ(boundary_faces(after), 72u);
  EXPECT_TRUE(isomorphic(after, read_jba(std::string(DARTCHECK_SOURCE_DIR) + "/../shared/jerboa-samples/cube-frame.jba").map));
}

// Inferred from one cube as in the paper, the rule has "20 nodes on its
// right-hand side", but the cube's 3-links are all loops: position 3 of
// every node is undecided (the example never shows a 3-sewn face). Kept
// as a relabeling (the paper's choice), the inner walls of the holes are
// 3-sewn to their counterparts in a neighbouring cube, so the rule applied
// to level 1 does not give level 2 (too few boundary squares). From two
// cubes sharing a face, every position is decided, and the rule applied to
// level 1 is level 2: the 400 cubes of a 9-grid with no base-3 digit
// position holding a 1 in two coordinates.
TEST(VolumeInference, MengerLevelTwoNeedsADecidingExample) {
  const auto level1 = refine(one_cube, 1, 3, menger_local);
  const auto level2 = refine(level1, 3, 3, menger_local);
  ASSERT_EQ(level2.size(), 400u);
  const Map oracle = polycube(level2, 9);

  const Attempt from_one = infer_refinement(one_cube, 1, 3, menger_local);
  ASSERT_TRUE(from_one.rule);
  EXPECT_EQ(from_one.rule->operation.rule.right().node_count(), 20u);
  std::size_t undecided_nodes = 0;
  for (const auto& u : from_one.scheme->undecided) undecided_nodes += u.position == 3;
  EXPECT_EQ(undecided_nodes, 20u);  // position 3 of every node of R
  const Map wrong = applied(from_one.rule->operation, polycube(level1, 3), 0);
  EXPECT_TRUE(check_map(wrong).valid());
  EXPECT_EQ(count_cells(wrong).cells[3], 400u);
  EXPECT_LT(boundary_faces(wrong), boundary_faces(oracle));

  const Attempt from_two = infer_refinement(two_cubes, 2, 3, menger_local);
  ASSERT_TRUE(from_two.rule);
  EXPECT_TRUE(from_two.scheme->undecided.empty());
  const Map two = applied(from_two.rule->operation, polycube(level1, 3), 0);
  ASSERT_EQ(two.size(), oracle.size());
  EXPECT_EQ(count_cells(two).cells, count_cells(oracle).cells);
  EXPECT_EQ(component_code(two, 0), component_code(oracle, 0));
}

// The (2,2,2)-Menger of Sec. 9.2.2: a 5-grid with the cubes that have two
// or three coordinates in {1, 3} removed (three tunnels per axis pair):
// 125 - 36 - 8 = 81 volumes. By hand: all 6^3 = 216 lattice points and the
// 3 x 6 x 6 x 5 = 540 lattice edges are used; of the 450 lattice squares,
// the 72 inside the tunnels (both other coordinates in {1,3}, 6 planes x 4
// x 3 axes) touch no kept cube: 378 faces, of which B = 2 x 378 - 6 x 81
// = 270 are on the boundary. Solid Euler 216 - 540 + 378 - 81 = -27 =
// 1 - g: genus 28. So the paper's "270 faces" are the boundary squares
// (the faces of the surface, 378 with the interior ones), its 216 vertices
// and genus 28 are those of the solid and of its boundary surface.
TEST(VolumeInference, MengerTwoTwoTwo) {
  const auto cubes = refine(one_cube, 1, 5, menger222_local);
  ASSERT_EQ(cubes.size(), 81u);
  const Map after = polycube(cubes, 5);
  ASSERT_TRUE(check_map(after).valid());
  EXPECT_EQ(count_cells(after).cells, (std::vector<std::size_t>{216, 540, 378, 81}));
  EXPECT_EQ(boundary_faces(after), 270u);
  const Attempt a = infer_refinement(one_cube, 1, 5, menger222_local);
  ASSERT_TRUE(a.rule);
  EXPECT_EQ(a.rule->operation.rule.right().node_count(), 81u);
  // From two cubes, applied to another pair: each cube refined, the pair
  // sewn along its shared face as the oracle says.
  const Attempt b = infer_refinement(two_cubes, 2, 5, menger222_local);
  ASSERT_TRUE(b.rule);
  const std::vector<std::array<std::uint32_t, 3>> column{{0, 0, 0}, {0, 0, 1}};
  const Map stacked = applied(b.rule->operation, polycube(column, 2), 0);
  const auto oracle_cubes = refine(column, 2, 5, menger222_local);
  const Map oracle = polycube(oracle_cubes, 10);
  EXPECT_TRUE(check_map(stacked).valid());
  EXPECT_EQ(count_cells(stacked).cells, count_cells(oracle).cells);
  EXPECT_EQ(component_code(stacked, 0), component_code(oracle, 0));
}

}  // namespace
}  // namespace dartcheck::inference::test
