// Cells given by the vertex cycles of their faces: what the shape builders,
// the mesh readers and query-modify's cell maps take.
#pragma once

#include <cstdint>
#include <vector>

namespace dartcheck {

/// A face as the cycle of its vertex indices.
using Polygon = std::vector<std::uint32_t>;
/// A volume as the faces that bound it.
using Polyhedron = std::vector<Polygon>;

}  // namespace dartcheck
