// Writing a 2-map with positions as an OFF or OBJ polygon mesh, the
// inverse of read_mesh + mesh_with_positions: one vertex per vertex orbit
// at its position, one face per face orbit.
#pragma once

#include <ostream>
#include <string>

#include "rewriting/embedded_map.hpp"

namespace dartcheck {

/// Writes `m` (a 2-G-map, valid) as OFF, or as OBJ when `path` ends in
/// .obj. Positions come from the embedding named `position` (point2 or
/// point3; point2 gets z = 0). Faces are <0,1>-orbits walked by alpha1
/// alpha0 from their smallest dart; boundary edges (2-loops) need nothing.
/// Throws InputError naming `path` when the map is not a 2-G-map, has no
/// such embedding, or a vertex has no position or two.
void write_mesh(std::ostream& out, const EmbeddedMap& m, const std::string& position, const std::string& path);

}  // namespace dartcheck
