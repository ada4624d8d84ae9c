#include "generators/mesh_map.hpp"

#include "core/input_error.hpp"
#include "generators/polygon_soup.hpp"

namespace dartcheck {

Map build_mesh(const Model& model, const Mesh& mesh) {
  try {
    return build_surface(model, mesh.faces);
  } catch (const BuildError& e) {
    const bool located = e.face() >= 0 && static_cast<std::size_t>(e.face()) < mesh.face_lines.size();
    throw InputError(mesh.file, located ? mesh.face_lines[static_cast<std::size_t>(e.face())] : 0, 0, e.what());
  }
}

Map load_mesh(const Model& model, const std::string& file) { return build_mesh(model, read_mesh(file)); }

}  // namespace dartcheck
