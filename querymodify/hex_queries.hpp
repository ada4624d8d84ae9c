// The queries of the tet -> hex recombination (001 Sec. 7.1): one oriented
// query per way a hexahedron can be cut into tetrahedra, mirror images
// included, each a tetrahedral 3-map whose boundary darts carry the '↔'
// condition (no 3-link to another matched dart), as the issue asks.
#pragma once

#include <cstdint>
#include <vector>

#include "querymodify/query_word.hpp"
#include "querymodify/tet_map.hpp"

namespace dartcheck::querymodify {

/// The tetrahedra of a subdivision (hex_subdivisions.hpp) as vertex
/// quadruples of the cube's corners.
std::vector<std::array<std::uint32_t, 4>> subdivision_tets(std::uint64_t subdivision);

/// enumerate_hex_subdivisions() as computed at build time (a generated
/// table, sorted): what the queries are built from.
const std::vector<std::uint64_t>& labeled_hex_subdivisions();

/// For each face of the hex (hex_faces() order), bit f set if the
/// subdivision splits it by the diagonal b-d of its cycle (a, b, c, d).
int subdivision_diagonals(std::uint64_t subdivision);

/// A map's canonical word: the smallest word over all start darts.
std::vector<std::uint32_t> canonical_word(const Map& m);

struct HexQuery {
  std::uint64_t subdivision = 0;  // a representative (vertices labeled)
  bool mirrored = false;          // built with every tetrahedron reflected
  std::size_t tets = 0;
  Map map{Model::open_omap(3)};
  QueryWord word;
  /// Every way to read the query's tetrahedra as a hexahedron: vertex
  /// permutations p such that p(tetrahedra) is again a labeled
  /// subdivision (the cube's symmetries, and more when the boundary
  /// triangles pair into quads in several ways). Reading p puts the
  /// query's vertex v at cube corner p[v].
  std::vector<std::array<std::uint8_t, 8>> readings;
};

/// One query per distinct oriented tetrahedral map among the 174 classes
/// and their mirror images (duplicates, the achiral classes, removed by
/// canonical word). 001 Sec. 7.1's queries, both hands. Built once from
/// the build-time table (about 0.2 s) and kept.
const std::vector<HexQuery>& hex_queries();

}  // namespace dartcheck::querymodify
