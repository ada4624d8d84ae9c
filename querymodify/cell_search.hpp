// Prisms and pyramids among the tetrahedra a hex recombination left
// (recombine --cells): the second and third passes of a hex-dominant
// recombination, as gmsh's Supplementary (prisms) and PostOp (pyramids)
// follow its Recombinator.
//
// A prism is 3 tetrahedra on 6 vertices that read as a labeled subdivision
// of the prism (cell_subdivisions.hpp); its tetrahedra form a path across
// two shared triangles (the outer two share only an edge, or they would
// span 5 vertices), so each candidate is found once, from its middle
// tetrahedron. The prism's 6 subdivisions into 5 tetrahedra are not looked
// for: they need two quads folded in (a prism twisted far enough that two
// quads' other diagonals pass inside), and such a prism stays tetrahedra. A pyramid is 2 tetrahedra on 5 vertices sharing a triangle;
// it is only looked for on a quad face of a selected hex or prism, where
// it turns a quad facing two triangles into a quad facing a quad: a
// pyramid anywhere else would put a quad against two triangles and make
// the mesh less conforming, not more.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace dartcheck::querymodify {

/// The tetrahedra on each triangle of a tetrahedral mesh.
class TetFaces {
 public:
  explicit TetFaces(const std::vector<std::array<std::uint32_t, 4>>& tets);
  /// The tetrahedra (one or two) with the triangle of vertices a, b, c
  /// (any order), none if no tetrahedron has it.
  std::span<const std::uint32_t> on(std::uint32_t a, std::uint32_t b, std::uint32_t c) const;
  /// The quad (a, b, c, d), a cycle, is split into two mesh triangles
  /// each of which has one tetrahedron only (on the mesh's boundary).
  bool quad_on_boundary(const std::array<std::uint32_t, 4>& quad) const;

 private:
  std::vector<std::array<std::uint32_t, 3>> triangles_;  // sorted, one per tetrahedron and face
  std::vector<std::uint32_t> tet_;                       // the tetrahedron of each entry
};

/// A prism or pyramid candidate: its tetrahedra, the mesh vertex at each
/// corner (cell_subdivisions.hpp; a pyramid uses 5) under its best reading
/// and that reading's quality (NaN without points).
struct CellCandidate {
  std::array<std::uint32_t, 3> tets{};
  std::uint32_t count = 0;
  std::array<std::uint32_t, 6> corners{};
  double quality = std::numeric_limits<double>::quiet_NaN();
  std::span<const std::uint32_t> tets_of() const { return {tets.data(), count}; }
};

struct CellCandidates {
  std::vector<CellCandidate> list;  // with points, those above the threshold only
  std::size_t found = 0;            // kept or not
};

/// Every prism made of tetrahedra not `used`; with points each is scored
/// by prism_quality over its readings and kept above `min_quality`.
CellCandidates find_prism_candidates(const std::vector<std::array<std::uint32_t, 4>>& tets, const TetFaces& faces, const std::vector<bool>& used,
                                     const std::vector<std::array<double, 3>>* points, double min_quality);

/// Every pyramid of two tetrahedra not `used` whose base is one of
/// `quads` (corner cycles), scored by pyramid_quality.
CellCandidates find_pyramid_candidates(const std::vector<std::array<std::uint32_t, 4>>& tets, const TetFaces& faces, const std::vector<bool>& used,
                                       const std::vector<std::array<std::uint32_t, 4>>& quads, const std::vector<std::array<double, 3>>* points,
                                       double min_quality);

/// The quads among `quads` (the quad faces of the cells, each listed once
/// per cell) that face neither the mesh's boundary nor the same quad of
/// another cell: a quad against triangles, where the mesh is not
/// conforming.
std::size_t quads_facing_triangles(const std::vector<std::array<std::uint32_t, 4>>& quads, const TetFaces& faces);

}  // namespace dartcheck::querymodify
