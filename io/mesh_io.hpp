// OFF and OBJ polygon meshes, read into a polygon soup that keeps the file
// line of every face so later errors can point at it.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace dartcheck {

struct Mesh {
  std::string file;
  std::vector<std::array<double, 3>> positions;
  std::vector<std::vector<std::uint32_t>> faces;  // vertex cycles
  std::vector<int> face_lines;                    // 1-based line of each face
};

/// Reads an .off or .obj file (chosen by extension, case-insensitive).
/// Throws InputError with file:line:column on anything malformed: a bad
/// header, a non-numeric token, a vertex index out of range, a face with
/// fewer than 3 vertices, a file that ends early, or no face at all.
Mesh read_mesh(const std::string& file);
Mesh read_off(const std::string& file);
Mesh read_obj(const std::string& file);

/// True if the path ends in .off or .obj.
bool is_mesh_path(const std::string& file);

}  // namespace dartcheck
