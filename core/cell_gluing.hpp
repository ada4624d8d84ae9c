// Gluing cells into maps: the one place where faces given as vertex cycles
// are matched along the faces cells share, and the one error type of every
// builder from cells, faces and shapes (generators' surfaces and volumes,
// query-modify's cell and tetrahedral meshes).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/map.hpp"
#include "core/polyhedron.hpp"

namespace dartcheck {

/// Cells, faces or a shape that make no map of the requested model: the
/// message says which face, edge or vertex and why; `culprit` and `index`
/// say which input element shows it, so that readers can name its line.
class BuildError : public Error {
 public:
  /// What `index` counts: the input's faces, or its cells (volumes, tetrahedra).
  enum class Culprit { none, face, cell };
  explicit BuildError(const std::string& message, Culprit culprit = Culprit::none, std::size_t index = 0)
      : Error(message), culprit_(culprit), index_(index) {}
  Culprit culprit() const { return culprit_; }
  std::size_t index() const { return index_; }

 private:
  Culprit culprit_;
  std::size_t index_;
};

/// Cells given flat, without one allocation per face (a tetrahedral mesh
/// has millions of faces): face f is vertices[face_begin[f] ..
/// face_begin[f+1]), cell c owns faces cell_begin[c] .. cell_begin[c+1].
struct CellComplex {
  std::vector<std::uint32_t> vertices;
  std::vector<std::size_t> face_begin{0};
  std::vector<std::size_t> cell_begin{0};

  void add_face(std::span<const std::uint32_t> face) {
    vertices.insert(vertices.end(), face.begin(), face.end());
    face_begin.push_back(vertices.size());
  }
  /// Closes the cell whose faces were added since the last call.
  void end_cell() { cell_begin.push_back(face_begin.size() - 1); }
  std::size_t faces() const { return face_begin.size() - 1; }
  std::size_t cells() const { return cell_begin.size() - 1; }
  std::span<const std::uint32_t> face(std::size_t f) const { return {vertices.data() + face_begin[f], face_begin[f + 1] - face_begin[f]}; }
  /// The cell of each face.
  std::vector<std::uint32_t> face_cells() const;

  static CellComplex of(const std::vector<Polyhedron>& cells);
};

/// The faces that have the same vertex set, as pairs (a, b), a < b, in
/// increasing order of a. Throws BuildError (the cell of the third face)
/// when more than two faces share a vertex set. O(V log F) for V
/// vertices in F faces.
std::vector<std::pair<std::size_t, std::size_t>> shared_faces(const CellComplex& complex);

/// The open 3-O-map of the cells (001 Def. 1): dart d is the edge from
/// complex.vertices[d] to the next vertex of its face, so darts follow the
/// order of the cells, their faces and the faces' vertices; β1 turns
/// around a face, β2 joins the two faces of a cell along an edge, β3 the
/// faces two cells share (free on the boundary). The faces of one cell are
/// oriented alike (all outward or all inward).
struct GluedCells {
  Map map{Model::open_omap(3)};
  std::vector<std::uint32_t> vertex;  // the vertex each dart starts from
  std::vector<std::uint32_t> cell;    // the cell each dart belongs to
};

/// Throws BuildError (Culprit::cell) on a face of fewer than 3 vertices or
/// with a repeated vertex, an edge of a cell not traversed exactly once in
/// each direction, a face in more than two cells or twice in one, and two
/// cells traversing their shared face the same way (inconsistent
/// orientations). O(D log D) for D darts.
GluedCells glue_cells(const CellComplex& complex);

}  // namespace dartcheck
