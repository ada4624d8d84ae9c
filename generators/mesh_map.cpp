#include "generators/mesh_map.hpp"

#include <fmt/format.h>

#include "core/input_error.hpp"
#include "core/limits.hpp"
#include "generators/polygon_soup.hpp"

namespace dartcheck {

Map build_mesh(const Model& model, const Mesh& mesh) {
  std::size_t corners = 0;
  for (const auto& f : mesh.faces) corners += f.size();
  // A 2-G-map has two darts per face corner, an O-map one.
  const std::size_t darts = model.is_generalized() ? 2 * corners : corners;
  if (darts > limits().darts) throw InputError(mesh.file, 0, 0, over_limit("the mesh's darts", darts, limits().darts, "--limit-darts"));
  try {
    return build_surface(model, mesh.faces);
  } catch (const BuildError& e) {
    const bool located = e.culprit() == BuildError::Culprit::face && e.index() < mesh.face_lines.size();
    throw InputError(mesh.file, located ? mesh.face_lines[e.index()] : 0, 0, e.what());
  }
}

Map load_mesh(const Model& model, const std::string& file) { return build_mesh(model, read_mesh(file)); }

EmbeddedMap mesh_with_positions(const Model& model, const Mesh& mesh, const EmbeddingSignature& pos) {
  if (!model.is_generalized() || model.dimension() < 2)
    throw InputError(mesh.file, 0, 0, fmt::format("positions from a mesh need an n-G-map with n >= 2, not a {}", model.name));
  if (pos.type != ValueType::point2 && pos.type != ValueType::point3)
    throw InputError(mesh.file, 0, 0, fmt::format("embedding {} is a {}; mesh positions are point2 or point3", pos.name, name_of(pos.type)));
  EmbeddedMap g(build_mesh(model, mesh));
  const std::size_t k = g.add_embedding(pos);
  std::vector<std::uint32_t> index(mesh.positions.size(), Embedding::none);
  Dart d = 0;
  for (const auto& f : mesh.faces)
    for (std::size_t e = 0; e < f.size(); ++e)
      for (std::uint32_t v : {f[e], f[(e + 1) % f.size()]}) {
        if (index[v] == Embedding::none) {
          auto p = mesh.positions[v];
          if (pos.type == ValueType::point2) p[2] = 0;
          index[v] = g.embeddings[k].store(Value::coords(pos.type, p));
        }
        g.embeddings[k].set_index(d++, index[v]);
      }
  if (d != g.map.size()) throw InputError(mesh.file, 0, 0, fmt::format("internal: {} darts numbered, the map has {}", d, g.map.size()));
  return g;
}

}  // namespace dartcheck
