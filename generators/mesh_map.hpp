// Polygon meshes (OFF/OBJ) as maps: faces sewn along shared edges.
#pragma once

#include "core/map.hpp"
#include "core/mesh_io.hpp"

namespace dartcheck {

/// Builds the surface of `mesh` in `model` (see build_surface). A
/// non-manifold edge or, for O-maps, an inconsistent orientation is an
/// InputError at the line of the offending face.
Map build_mesh(const Model& model, const Mesh& mesh);

/// read_mesh + build_mesh.
Map load_mesh(const Model& model, const std::string& file);

}  // namespace dartcheck
