// Building maps from cells given as vertex cycles: the common ground of the
// shape builders and of the OFF/OBJ importer.
#pragma once

#include <vector>

#include "core/cell_gluing.hpp"

namespace dartcheck {

/// Sews the faces along shared edges into a surface.
///
/// G-maps (n >= 2): each face corner-side becomes a dart; faces sharing an
/// edge are 2-sewn; a boundary edge gets 2-loops; dimensions above 2 get
/// loops. Works for non-orientable surfaces.
/// 2-O-maps: each face side becomes a dart (a half-edge), 2-links pair
/// opposite half-edges, and the boundary is closed by outer faces (002
/// Example 5); faces must be consistently oriented.
/// Throws BuildError on a face with fewer than 3 vertices or a repeated
/// vertex, an edge shared by more than two faces, or (O-maps) two faces
/// traversing an edge in the same direction.
Map build_surface(const Model& model, const std::vector<Polygon>& faces);

/// Builds each volume as a surface of an n-G-map (n >= 3) and 3-sews faces
/// of different volumes that have the same vertex set; faces met by no
/// other volume get 3-loops; faces are matched by shared_faces
/// (core/cell_gluing.hpp). Throws BuildError when a face is shared by more
/// than two volumes or two faces have the same vertices but not the same
/// edges.
Map build_volumes(const Model& model, const std::vector<Polyhedron>& volumes);

}  // namespace dartcheck
