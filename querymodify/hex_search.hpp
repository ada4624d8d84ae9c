// The fast path of the tet -> hex recombination: candidate hexahedra
// found from mesh vertices and edges, the vertex-based search of Pellerin,
// Verhetsel and Remacle 2018 that 001 compares with, instead of matching
// the 322 query words from every dart (docs/querymodify.md, "Search").
//
// What it finds is defined by 001's word matching (hex_queries.hpp,
// annotation.hpp): a set of tetrahedra is a candidate iff some hex query
// matches it with the query's 8 corners at 8 distinct mesh vertices, the
// only matches the recombination can select. Such a match is exactly a
// labeled subdivision (hex_subdivisions.hpp) of a cube whose corners are
// 8 distinct mesh vertices, each of its tetrahedra a mesh tetrahedron:
// the query's inner triangles are shared faces, which build_tet_map
// glues, and a boundary triangle of the query ('↔') is never glued to
// another tetrahedron of the set, which would share its 3 corners and so
// be glued in the query too. tests/querymodify/test_hex_search.cpp
// compares the two searches on random members of all 174 classes and on
// real meshes.
//
// How: corner 0 is the smallest of the 8 vertices, so every tetrahedron
// of a hex has its smallest vertex at or above it, and the three quad
// faces at corner 0 are each two triangles of the tetrahedra whose
// smallest vertex is corner 0 (one triangle, when the quad's diagonal
// avoids corner 0, the other a triangle of a tetrahedron above it). Three
// such quads sharing their edges (corners 1 < 2 < 4: one labeling per
// cube structure) and a common neighbour of corners 3, 5 and 6 give the
// 8 corners; the mesh tetrahedra on them, as a set of the 64 candidate
// tetrahedra of the cube, must contain a labeled subdivision.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "querymodify/progress.hpp"

namespace dartcheck::querymodify {

/// One candidate: its tetrahedra (sorted mesh indices, in the pool of
/// HexCandidates) and its best reading as a hexahedron.
struct HexCandidate {
  std::uint32_t first = 0;  // HexCandidates::tets[first, first + count)
  std::uint32_t count = 0;
  /// The mesh vertex at each cube corner (v = x + 2y + 4z) under the
  /// reading with the best scaled Jacobian (the first found without
  /// points), and that value (NaN without points).
  std::array<std::uint32_t, 8> corners{};
  double quality = std::numeric_limits<double>::quiet_NaN();
};

struct HexCandidates {
  /// In the order found (corner 0 increasing); with points, only those
  /// above the threshold.
  std::vector<HexCandidate> list;
  /// Candidates found, kept or not.
  std::size_t found = 0;
  std::vector<std::uint32_t> tets;
  /// Readings found: (cube labeling up to the cube's symmetries, labeled
  /// subdivision) pairs; a candidate whose triangles pair into quads in
  /// several ways is read more than once.
  std::size_t readings = 0;
  std::span<const std::uint32_t> tets_of(const HexCandidate& c) const { return {tets.data() + c.first, c.count}; }
};

/// Every candidate hexahedron of the mesh `tets` (vertex indices; the
/// tetrahedra may be given in either orientation). With `points`, each is
/// scored by scaled_jacobian (exact signs, hex_quality.hpp) over its
/// readings and kept only if its quality is above `min_quality` (all
/// readings of a candidate share its corner 0, so each is judged as soon
/// as its corner 0 is done). O(V + T) memory besides the kept candidates,
/// one pass over the vertices.
/// `progress` hears how many corner-0 vertices are done, every 16,384.
HexCandidates find_hex_candidates(const std::vector<std::array<std::uint32_t, 4>>& tets, const std::vector<std::array<double, 3>>* points = nullptr,
                                  double min_quality = -std::numeric_limits<double>::infinity(), const Progress& progress = {});

}  // namespace dartcheck::querymodify
