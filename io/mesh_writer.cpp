#include "io/mesh_writer.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "core/input_error.hpp"
#include "core/orbit.hpp"
#include "io/gmsh_msh.hpp"
#include "io/vtk_writer.hpp"

namespace dartcheck {

PolygonMesh polygon_mesh(const EmbeddedMap& m, const std::string& position, const std::string& path) {
  const Map& map = m.map;
  const Model& model = map.model();
  auto fail = [&](const std::string& why) { throw InputError(path, 0, 0, why); };
  // Positions live on 2-G-maps (generators/mesh_map): O-maps have no
  // embedded maps to write.
  if (model != Model::gmap(2)) fail(fmt::format("a polygon mesh is written from a 2-gmap with positions; this map is a {}", model.name));
  const Embedding* pos = m.find(position);
  if (!pos) fail(fmt::format("the map has no embedding '{}' to give the vertices their positions", position));
  if (pos->signature.type != ValueType::point3 && pos->signature.type != ValueType::point2)
    fail(fmt::format("embedding '{}' holds {}, not point3 or point2", position, name_of(pos->signature.type)));

  // Vertices, numbered in order of their smallest dart.
  std::vector<std::uint32_t> vertex(map.size());
  PolygonMesh out;
  auto& points = out.points;
  OrbitWalker walker(map);
  for_each_orbit(walker, map, cell_generators(model, 0), [&](Dart d, const std::vector<Dart>& orbit) {
    const Value* v = nullptr;
    for (Dart e : orbit) {
      vertex[e] = static_cast<std::uint32_t>(points.size());
      const Value* w = pos->value(e);
      if (!w) fail(fmt::format("dart {} (vertex {}) has no {}", e, points.size(), position));
      if (v && !(*v == *w))
        fail(fmt::format("vertex {} has two {} values, {} and {} (darts {} and {})", points.size(), position, v->str(), w->str(), d, e));
      v = w;
    }
    points.push_back(v->x);
  });
  // Faces: walk alpha1 alpha0 around each <0,1>-orbit from its smallest dart.
  for_each_orbit(walker, map, dims_generators({0, 1}), [&](Dart d, const std::vector<Dart>&) {
    std::vector<std::uint32_t> face;
    out.first_dart.push_back(d);
    Dart e = d;
    do {
      face.push_back(vertex[e]);
      e = map.link(1, map.link(0, e));
    } while (e != d);
    out.faces.push_back(std::move(face));
  });
  return out;
}

bool is_polygon_mesh_output(const std::string& path) {
  const std::string e = std::filesystem::path(path).extension().string();
  return e == ".off" || e == ".obj" || e == ".vtu" || e == ".vtk" || e == ".msh";
}

void write_mesh(std::ostream& out, const EmbeddedMap& m, const std::string& position, const std::string& path) {
  const PolygonMesh mesh = polygon_mesh(m, position, path);
  const auto& points = mesh.points;
  const auto& faces = mesh.faces;
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".vtu" || ext == ".vtk") {
    if (ext == ".vtu")
      write_vtu(out, points, polygon_cells(faces));
    else
      write_legacy_vtk(out, points, polygon_cells(faces));
    return;
  }
  if (ext == ".msh") {
    for (std::size_t k = 0; k < faces.size(); ++k)
      if (faces[k].size() > 4)
        throw InputError(path, 0, 0,
                         fmt::format("gmsh has no element for a face of {} corners (face {}, from dart {}); write .vtu, .vtk, .off or .obj", faces[k].size(), k,
                                     mesh.first_dart[k]));
    write_gmsh(out, points, polygon_cells(faces), 2);
    return;
  }
  if (ext == ".obj") {
    out << "# written by dartcheck: " << points.size() << " vertices, " << faces.size() << " faces\n";
    for (const auto& p : points) out << fmt::format("v {} {} {}\n", p[0], p[1], p[2]);
    for (const auto& f : faces) {
      out << 'f';
      for (auto v : f) out << ' ' << v + 1;
      out << '\n';
    }
    return;
  }
  out << "OFF\n" << points.size() << ' ' << faces.size() << " 0\n";
  for (const auto& p : points) out << fmt::format("{} {} {}\n", p[0], p[1], p[2]);
  for (const auto& f : faces) {
    out << f.size();
    for (auto v : f) out << ' ' << v;
    out << '\n';
  }
}

}  // namespace dartcheck
