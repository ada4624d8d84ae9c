// 001 Sec. 7.4: a voxel terrain with houses, the experiment behind Table 2.
// (1) a height map by diamond-square and one voxel per height-map cell,
// its bottom face split into two triangles; (2) flat spots made by a
// query-apply: the query is 3x3 such voxels, the apply merges the nine
// volumes and their upper faces and sets the merged face to the mean
// height of its original points; (3) houses added by a query-extend: the
// query is the flattened spot, the target the spot with a house on it.
// Each step is the library's query matching and modify operations; this
// file only builds the meshes and the apply function, as 001 describes.
#pragma once

#include <cstdint>
#include <vector>

#include "core/map.hpp"
#include "querymodify/annotation.hpp"
#include "core/cell_gluing.hpp"
#include "querymodify/geometry.hpp"
#include "querymodify/modify.hpp"

namespace dartcheck::querymodify::terrain {

/// A 3-map with a point per dart (the point of the vertex it starts at).
struct Mesh {
  Map map{Model::open_omap(3)};
  std::vector<Point3> points;
};

/// Heights on a (2^k + 1)^2 grid by the diamond-square method (001's
/// [16]), row-major, seeded, scaled into [low, high].
std::vector<double> diamond_square(unsigned k, std::uint64_t seed, double low, double high);

/// n x n voxels on the height map `heights` ((n + 1)^2 values, row-major):
/// voxel (i, j) spans [i, i+1] x [j, j+1] from z = 0 to the heights at its
/// four upper corners; its faces are oriented outward and its bottom is
/// split by the diagonal from (i, j) to (i+1, j+1). 26 darts per voxel.
std::vector<Polyhedron> voxel_cells(std::uint32_t n);
std::vector<Point3> voxel_points(std::uint32_t n, const std::vector<double>& heights);
Mesh voxel_grid(std::uint32_t n, const std::vector<double>& heights);

/// Step (2)'s query: 3 x 3 voxels of height 1, and its upper-face darts.
struct SpotQuery {
  Mesh mesh;
  std::vector<Dart> upper;
};
SpotQuery spot_query();

/// Step (2)'s apply function on one match (`q_to_m`: the input dart of
/// each query dart): the nine volumes merged into one (merge_volumes), its
/// nine upper faces merged into one (merge_faces), and every vertex of
/// that face set to the mean height of the 16 upper points it had.
/// `points` follow the darts' renumbering, which is returned.
Renumbering flatten_spot(Mesh& m, const SpotQuery& q, const std::vector<Dart>& q_to_m);

/// Step (3)'s query and target. The query is the flattened spot as one
/// volume ([0, 3]^2 x [0, 1]: a 12-gon on top, 12 side quads, 18 bottom
/// triangles; 114 darts); the target is that volume (its first 114 darts,
/// so m_QT is the identity) with a house of three volumes on its upper
/// face: a storey and a second storey (prisms over the 12-gon, 72 darts
/// each) and a pyramid roof (48 darts).
struct HouseRule {
  Mesh query, target;
  std::vector<Dart> upper;  // the query's upper-face darts
};
HouseRule house_rule();

/// A row of 001's Table 2, with the matches behind it.
struct Step {
  std::size_t volumes = 0, darts = 0;
  double query_seconds = 0, modify_seconds = 0;
  std::size_t raw_matches = 0, distinct_matches = 0, applied = 0;
};

/// A house as placed: the input points of its roof's apex and of its
/// spot's upper face (their mean is the spot's centre and height).
struct PlacedHouse {
  Point3 apex, spot_centre;
};

struct Experiment {
  Mesh mesh;
  Step grid, flattened, housed;
  std::vector<PlacedHouse> houses;
};

/// The three steps on an n x n grid (n + 1 = 2^k + 1 for the height map)
/// with `spots` flat spots: step (2) takes distinct matches in a seeded
/// random order, each unless it shares a mesh vertex with one taken
/// before (flattening moves the shared vertices, so neighbouring spots
/// would unflatten each other), until `spots` are taken; step (3) extends
/// every distinct match of the spot query. Throws Error if
/// fewer than `spots` vertex-disjoint spots exist.
Experiment run_experiment(unsigned k, std::size_t spots, std::uint64_t seed);

}  // namespace dartcheck::querymodify::terrain
