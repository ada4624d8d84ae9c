// Polygon meshes (OFF/OBJ) as maps: faces sewn along shared edges.
#pragma once

#include "rewriting/embedded_map.hpp"
#include "core/map.hpp"
#include "io/mesh_io.hpp"

namespace dartcheck {

/// Builds the surface of `mesh` in `model` (see build_surface). A
/// non-manifold edge or, for O-maps, an inconsistent orientation is an
/// InputError at the line of the offending face.
Map build_mesh(const Model& model, const Mesh& mesh);

/// read_mesh + build_mesh.
Map load_mesh(const Model& model, const std::string& file);

/// build_mesh for an n-G-map (n >= 2) with the file's vertex positions as
/// the embedding `pos` (a point2 drops z, a point3 keeps it): the dart of
/// face f at corner e lies at vertex f[e] (build_surface's numbering).
EmbeddedMap mesh_with_positions(const Model& model, const Mesh& mesh, const EmbeddingSignature& pos);

}  // namespace dartcheck
