// Writing a 2-map with positions as a polygon mesh (OFF, OBJ, VTK XML
// .vtu, legacy .vtk, gmsh .msh 4.1), the inverse of read_mesh +
// mesh_with_positions: one vertex per vertex orbit at its position, one
// face per face orbit.
#pragma once

#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "rewriting/embedded_map.hpp"

namespace dartcheck {

/// The polygon mesh of `m`: its points, and its faces as corner lists,
/// each with the dart its walk started from. Same conditions and errors
/// as write_mesh.
struct PolygonMesh {
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::uint32_t>> faces;
  std::vector<Dart> first_dart;
};
PolygonMesh polygon_mesh(const EmbeddedMap& m, const std::string& position, const std::string& path);

/// Whether `path` ends in an extension write_mesh writes.
bool is_polygon_mesh_output(const std::string& path);

/// Writes `m` (a 2-G-map, valid) in the format `path`'s extension names:
/// .off (the default), .obj, .vtu, .vtk or .msh (triangles and
/// quadrangles only: gmsh has no polygon element; InputError otherwise).
/// Positions come from the embedding named `position` (point2 or point3;
/// point2 gets z = 0). Faces are <0,1>-orbits walked by alpha1
/// alpha0 from their smallest dart; boundary edges (2-loops) need nothing.
/// Throws InputError naming `path` when the map is not a 2-G-map, has no
/// such embedding, or a vertex has no position or two.
void write_mesh(std::ostream& out, const EmbeddedMap& m, const std::string& position, const std::string& path);

}  // namespace dartcheck
