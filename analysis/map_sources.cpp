#include "analysis/map_sources.hpp"

#include <filesystem>
#include <fmt/format.h>

#include "core/input_error.hpp"
#include "io/jerboa_jba.hpp"
#include "io/map_io.hpp"
#include "io/mesh_io.hpp"
#include "generators/mesh_map.hpp"
#include "generators/shapes.hpp"

namespace dartcheck::analysis {

Catalog read_rule_catalog(const std::string& file, const std::string& rule) {
  Catalog catalog = read_catalog(file);
  if (!rule.empty() && !catalog.find_rule(rule))
    throw InputError("<command line>", 0, 0, fmt::format("--rule: no rule named '{}' in {}", rule, file));
  return catalog;
}

Map build_source(const MapSource& s) {
  if (s.map) return *s.map;
  if (!s.mesh.empty()) return load_mesh(s.model, s.mesh);
  try {
    return build_shape(s.model, parse_shape(s.shape));
  } catch (const BuildError& e) {
    throw InputError(s.location.file, s.location.line, s.location.column, fmt::format("map '{}': {}", s.name, e.what()));
  }
}

Map resolve_map(const std::string& target, const Model& model, const Catalog* catalog) {
  if (catalog)
    if (const MapSource* s = catalog->find_map(target)) return build_source(*s);
  const bool exists = std::filesystem::exists(target);
  if (is_mesh_path(target)) return load_mesh(model, target);
  const auto ext = std::filesystem::path(target).extension().string();
  if (ext == ".yaml" || ext == ".yml") return read_map_file(target);
  if (ext == ".jba") return read_jba(target).map;  // the file names its dimension
  if (exists) throw InputError(target, 0, 0, "unknown map file type (expected .yaml, .yml, .off, .obj or .jba)");
  try {
    return build_shape(model, parse_shape(target));
  } catch (const BuildError& e) {
    throw InputError("<command line>", 0, 0, fmt::format("'{}' is not a catalog map, a map file or a shape: {}", target, e.what()));
  }
}

std::string describe_target(const std::string& target, const Map& map) {
  return fmt::format("{} ({}, {} darts)", target, map.model().name, map.size());
}

}  // namespace dartcheck::analysis
